#include "micro/contact/piecewise_power_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/errors.h"

namespace softglass::micro {

namespace {
double branch_energy(const PiecewisePowerLaw::Branch& b, double eps) {
  // ∫ a ε^n dε = a ε^{n+1}/(n+1)
  return b.prefactor * std::pow(eps, b.exponent + 1.0) / (b.exponent + 1.0);
}
}  // namespace

PiecewisePowerLaw::PiecewisePowerLaw(std::vector<Branch> branches)
    : branches_(std::move(branches)) {
  if (branches_.empty() || branches_.front().start != 0.0) {
    throw std::invalid_argument("a piecewise power law must start at deformation 0");
  }
  for (std::size_t k = 0; k < branches_.size(); ++k) {
    const Branch& b = branches_[k];
    if (!(b.prefactor > 0.0) || !(b.exponent > 0.0) || !std::isfinite(b.exponent)) {
      throw std::invalid_argument("power-law branch " + std::to_string(k) +
                                  " needs a positive prefactor and exponent");
    }
    if (k > 0) {
      const Branch& prev = branches_[k - 1];
      if (!(b.start > prev.start)) throw std::invalid_argument("branch starts must increase");
      const double left = prev.prefactor * std::pow(b.start, prev.exponent);
      const double right = b.prefactor * std::pow(b.start, b.exponent);
      if (std::abs(left - right) > 1e-9 * std::max(left, right)) {
        throw std::invalid_argument("power-law branches do not join at deformation " +
                                    std::to_string(b.start));
      }
    }
    kinds_.push_back(b.exponent == 1.5   ? Kind::three_halves
                     : b.exponent == 2.0 ? Kind::two
                     : b.exponent == 3.0 ? Kind::three
                                         : Kind::general);
  }
  // The energy at each branch's start, summed over the branches below it.
  double at_start = 0.0;
  for (std::size_t k = 0; k < branches_.size(); ++k) {
    const Branch& b = branches_[k];
    if (k > 0) {
      const Branch& prev = branches_[k - 1];
      at_start += branch_energy(prev, b.start) - branch_energy(prev, prev.start);
    }
    energy_factor_.push_back(b.prefactor / (b.exponent + 1.0));
    energy_offset_.push_back(at_start - branch_energy(b, b.start));
  }
}

PiecewisePowerLaw PiecewisePowerLaw::continuous(const std::string& what, double first_c,
                                                const std::vector<double>& breakpoints,
                                                const std::vector<double>& exponents) {
  require(exponents.size() == breakpoints.size() + 1,
          fmt::format("{}: {} exponents for {} breakpoints; allowed: one exponent more than "
                      "breakpoints",
                      what, exponents.size(), breakpoints.size()));
  require(std::isfinite(first_c) && first_c > 0.0,
          fmt::format("{}: C = {} must be positive", what, first_c));
  for (std::size_t k = 0; k < breakpoints.size(); ++k) {
    const double previous = k == 0 ? 0.0 : breakpoints[k - 1];
    require(std::isfinite(breakpoints[k]) && breakpoints[k] > previous,
            fmt::format("{}: breakpoints must be positive and increase; got {} after {}", what,
                        breakpoints[k], previous));
  }
  for (double n : exponents)
    require(std::isfinite(n) && n > 0.0, fmt::format("{}: exponent {} must be positive", what, n));
  std::vector<Branch> branches{{0.0, (4.0 / 3.0) * first_c, exponents[0]}};
  for (std::size_t k = 0; k < breakpoints.size(); ++k) {
    // a_k ε_k^{n_k} = a_{k−1} ε_k^{n_{k−1}} at the breakpoint ε_k
    const Branch& below = branches.back();
    const double e = breakpoints[k];
    branches.push_back(
        {e, below.prefactor * std::pow(e, below.exponent - exponents[k + 1]), exponents[k + 1]});
  }
  return PiecewisePowerLaw(std::move(branches));
}

std::size_t PiecewisePowerLaw::bisect(double eps) const {
  // The first branch starting at or above ε is the one after ε's branch.
  const auto it = std::lower_bound(branches_.begin() + 1, branches_.end(), eps,
                                   [](const Branch& b, double e) { return b.start < e; });
  return static_cast<std::size_t>(it - branches_.begin()) - 1;
}

}  // namespace softglass::micro
