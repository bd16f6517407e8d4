#include "macro/exact/rate_moment.h"

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

}  // namespace softglass::macro::exact
