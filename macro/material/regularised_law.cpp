#include "macro/material/regularised_law.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "common/errors.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro {

// Each regularisation lives in its own file and provides its factory.
std::unique_ptr<RegularisedLaw> make_papanastasiou(const HerschelBulkley&, double);
std::unique_ptr<RegularisedLaw> make_bercovier_engelman(const HerschelBulkley&, double);

namespace {

struct RegisteredRegularisation {
  const char* name;
  std::unique_ptr<RegularisedLaw> (*make)(const HerschelBulkley&, double);
};
constexpr std::array kRegistry{
    RegisteredRegularisation{"papanastasiou", make_papanastasiou},
    RegisteredRegularisation{"bercovier-engelman", make_bercovier_engelman},
};

}  // namespace

RegularisedLaw::RegularisedLaw(const HerschelBulkley& law, double rate_scale)
    : law_(law), rate_scale_(rate_scale) {}

Viscosity RegularisedLaw::viscosity(double rate) const {
  // The power-law term K s^{(n−1)/2}, s = γ̇² + ε², and its γ̇-derivative
  // K (n−1) γ̇ s^{(n−3)/2}; both exact (K and 0) for n = 1.
  const double n = law_.flow_index;
  const double s = rate * rate + rate_scale_ * rate_scale_;
  const double power = law_.consistency * std::pow(s, 0.5 * (n - 1.0));
  const Viscosity yield = yield_term(rate);
  return {.value = yield.value + power, .derivative = yield.derivative + (n - 1.0) * rate * power / s};
}

double RegularisedLaw::stress(double rate) const { return viscosity(rate).value * rate; }

double RegularisedLaw::tangent(double rate) const {
  const Viscosity eta = viscosity(rate);
  return eta.value + rate * eta.derivative;
}

double RegularisedLaw::rate(double stress) const {
  if (stress <= 0.0) return 0.0;
  // The unregularised rate is a good first bracket (exact for Newtonian, a
  // lower bound for n ≤ 1); solve_increasing widens it if needed.
  const double guess = std::max(law_.rate(stress), rate_scale_);
  return numerics::solve_increasing([&](double r) { return this->stress(r) - stress; }, 0.0, guess,
                                    fmt::format("{} rate at stress {}", name(), stress));
}

std::unique_ptr<RegularisedLaw> make_regularised_law(std::string_view name,
                                                     const HerschelBulkley& law, double rate_scale) {
  require(std::isfinite(rate_scale) && rate_scale > 0.0,
          fmt::format("regularisation rate scale = {} is not allowed; allowed: > 0 (1/s)", rate_scale));
  for (const auto& entry : kRegistry) {
    if (name == entry.name) return entry.make(law, rate_scale);
  }
  throw InputError(fmt::format("regularisation '{}' is unknown; allowed: {}", name,
                               fmt::join(regularisation_names(), ", ")));
}

std::vector<std::string> regularisation_names() {
  std::vector<std::string> names;
  for (const auto& entry : kRegistry) names.emplace_back(entry.name);
  return names;
}

}  // namespace softglass::macro
