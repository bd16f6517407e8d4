#include "macro/exact/parallel_plates.h"

#include <cmath>
#include <numbers>

namespace softglass::macro::exact {

namespace {

// 2πR³, the torque per unit of the bracket.
double torque_scale(const ParallelPlates& plates) {
  return 2.0 * std::numbers::pi * std::pow(plates.radius, 3);
}

// π∫₀^R N(γ̇_R r/R) r dr / (πR²) = N_y/2 + K_N γ̇_R^{n_N}/(n_N + 2).
double weighted_mean(const NormalStressLaw& law, double rim_rate) {
  return 0.5 * law.yield + law.consistency * std::pow(rim_rate, law.flow_index) / (law.flow_index + 2.0);
}

}  // namespace

double rim_rate(const ParallelPlates& plates, double rotation_rate) {
  return rotation_rate * plates.radius / plates.gap;
}

double torque(const HerschelBulkley& law, const ParallelPlates& plates, double rotation_rate) {
  const double n = law.flow_index;
  return torque_scale(plates) *
         (law.yield_stress / 3.0 +
          law.consistency * std::pow(rim_rate(plates, rotation_rate), n) / (n + 3.0));
}

double rotation_rate(const HerschelBulkley& law, const ParallelPlates& plates, double torque) {
  const double n = law.flow_index;
  const double excess = torque / torque_scale(plates) - law.yield_stress / 3.0;
  if (excess <= 0.0) return 0.0;
  return std::pow((n + 3.0) * excess / law.consistency, 1.0 / n) * plates.gap / plates.radius;
}

double normal_force(const NormalStressLaw& n1, const NormalStressLaw& n2,
                    const ParallelPlates& plates, double rotation_rate) {
  const double rate = rim_rate(plates, rotation_rate);
  return std::numbers::pi * plates.radius * plates.radius *
         (weighted_mean(n1, rate) - weighted_mean(n2, rate));
}

}  // namespace softglass::macro::exact
