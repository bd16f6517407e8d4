#include "macro/material/regularised_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "macro/material/regularisations/registered_regularisations.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro {

#define SOFTGLASS_DECLARE_REGULARISATION(name) RegularisationEntry name##_regularisation();
SOFTGLASS_REGULARISATIONS(SOFTGLASS_DECLARE_REGULARISATION)
#undef SOFTGLASS_DECLARE_REGULARISATION

const Registry<RegularisationEntry>& regularisations() {
#define SOFTGLASS_LIST_REGULARISATION(name) name##_regularisation(),
  static const Registry<RegularisationEntry> registry(
      "regularisation", {SOFTGLASS_REGULARISATIONS(SOFTGLASS_LIST_REGULARISATION)});
#undef SOFTGLASS_LIST_REGULARISATION
  return registry;
}

RegularisedLaw::RegularisedLaw(const ShearLaw& law, double rate_scale)
    : law_(law), rate_scale_(rate_scale) {}

Viscosity RegularisedLaw::viscosity(double rate) const {
  const Viscosity yield = yield_term(rate);
  const Viscosity flow = law_.regularised_flow_viscosity(rate, rate_scale_);
  return {.value = yield.value + flow.value, .derivative = yield.derivative + flow.derivative};
}

double RegularisedLaw::stress(double rate) const {
  return viscosity(rate).value * rate;
}

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

std::unique_ptr<RegularisedLaw> make_regularised_law(std::string_view name, const ShearLaw& law,
                                                     double rate_scale) {
  require(
      std::isfinite(rate_scale) && rate_scale > 0.0,
      fmt::format("regularisation rate scale = {} is not allowed; allowed: > 0 (1/s)", rate_scale));
  return regularisations().at(std::string(name)).make({.law = law, .rate_scale = rate_scale});
}

}  // namespace softglass::macro
