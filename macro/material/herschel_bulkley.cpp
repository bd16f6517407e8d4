#include "macro/material/herschel_bulkley.h"

#include <algorithm>
#include <cmath>

#include "macro/numerics/root_finding.h"

namespace softglass::macro {

double HerschelBulkley::stress(double rate) const {
  return yield_stress + consistency * std::pow(rate, flow_index);
}

double HerschelBulkley::rate(double stress) const {
  return stress <= yield_stress ? 0.0 : rate_at_excess(stress - yield_stress);
}

double HerschelBulkley::rate_at_excess(double excess) const {
  return std::pow(excess / consistency, 1.0 / flow_index);
}

double HerschelBulkley::viscosity(double rate) const {
  // τ_y/γ̇ is written only for τ_y > 0, so that a power law at γ̇ = 0 gives
  // K·0^{n−1} (K for n = 1, 0 for n > 1) rather than 0/0.
  const double plastic = yield_stress > 0.0 ? yield_stress / rate : 0.0;
  return plastic + consistency * std::pow(rate, flow_index - 1.0);
}

double HerschelBulkley::proximal_rate(double trial_stress, double penalty) const {
  const double excess = trial_stress - yield_stress;
  if (excess <= 0.0) return 0.0;
  if (flow_index == 1.0) return excess / (consistency + penalty);
  // Both terms of K sⁿ + r s are non-negative and increasing, so the root lies
  // below the value at which either alone reaches the excess stress.
  double upper = rate(trial_stress);
  if (penalty > 0.0) upper = std::min(upper, excess / penalty);
  return numerics::solve_increasing(
      [&](double s) { return consistency * std::pow(s, flow_index) + penalty * s - excess; }, 0.0,
      upper, "Herschel-Bulkley proximal rate");
}

HerschelBulkley bingham(double yield_stress, double plastic_viscosity) {
  return {.yield_stress = yield_stress, .consistency = plastic_viscosity, .flow_index = 1.0};
}

HerschelBulkley power_law(double consistency, double flow_index) {
  return {.yield_stress = 0.0, .consistency = consistency, .flow_index = flow_index};
}

HerschelBulkley newtonian(double viscosity) {
  return {.yield_stress = 0.0, .consistency = viscosity, .flow_index = 1.0};
}

}  // namespace softglass::macro
