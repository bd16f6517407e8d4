#include "macro/exact/rate_moment.h"

#include <algorithm>
#include <cmath>

#include "macro/numerics/quadrature.h"

namespace softglass::macro::exact {

double rate_moment(const RegularisedLaw& law, int power, double from, double to) {
  const auto integrand = [&](double tau) { return std::pow(tau, power) * law.rate(tau); };
  const double tau_y = law.law().yield_stress();
  if (from < tau_y && tau_y < to) {
    return numerics::integrate(integrand, from, tau_y) + numerics::integrate(integrand, tau_y, to);
  }
  return numerics::integrate(integrand, from, to);
}

double rate_moment(const ShearLaw& law, int power, double from, double to) {
  const double tau_y = law.yield_stress(), lo = std::max(from, tau_y) - tau_y, hi = to - tau_y;
  if (hi <= lo) return 0.0;
  return numerics::integrate(
      [&](double e) { return std::pow(tau_y + e, power) * law.rate_at_excess(e); }, lo, hi,
      law.excess_breakpoints());
}

}  // namespace softglass::macro::exact
