#include "macro/exact/parallel_plates.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "macro/numerics/quadrature.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro::exact {

namespace {

// 2πR³, the torque per unit of the bracket.
double torque_scale(const ParallelPlates& plates) {
  return 2.0 * std::numbers::pi * std::pow(plates.radius, 3);
}

// γ̇_R⁻³ ∫₀^{γ̇_R} Δ(γ̇) γ̇² dγ̇, split at the rates of the law's breakpoints.
double excess_moment(const ShearLaw& law, double rim_rate) {
  if (rim_rate <= 0.0) return 0.0;
  std::vector<double> cuts;
  for (const double excess : law.excess_breakpoints()) cuts.push_back(law.rate_at_excess(excess));
  const double integral = numerics::integrate(
      [&](double rate) { return law.excess_stress(rate) * rate * rate; }, 0.0, rim_rate, cuts);
  return integral / (rim_rate * rim_rate * rim_rate);
}

}  // namespace

double rim_rate(const ParallelPlates& plates, double rotation_rate) {
  return rotation_rate * plates.radius / plates.gap;
}

double torque(LawRef law, const ParallelPlates& plates, double rotation_rate) {
  return torque_scale(plates) *
         (law->yield_stress() / 3.0 + excess_moment(*law, rim_rate(plates, rotation_rate)));
}

double rotation_rate(LawRef law, const ParallelPlates& plates, double torque) {
  const double excess = torque / torque_scale(plates) - law->yield_stress() / 3.0;
  if (excess <= 0.0) return 0.0;
  const double rim = numerics::solve_increasing(
      [&](double rate) { return excess_moment(*law, rate) - excess; },
      law->rate_at_excess(3.0 * excess), 2.0 * law->rate_at_excess(24.0 * excess / 7.0),
      "parallel-plate rotation rate");
  return rim * plates.gap / plates.radius;
}

double normal_force(const NormalStressCurve& n1, const NormalStressCurve& n2,
                    const ParallelPlates& plates, double rotation_rate) {
  const double rim = rim_rate(plates, rotation_rate);
  const double area = std::numbers::pi * plates.radius * plates.radius;
  if (rim <= 0.0) return area * (n1.value(0.0) - n2.value(0.0)) / 2.0;
  std::vector<double> cuts = n1.rate_breakpoints();
  const std::vector<double> more = n2.rate_breakpoints();
  cuts.insert(cuts.end(), more.begin(), more.end());
  const double integral = numerics::integrate(
      [&](double rate) { return (n1.value(rate) - n2.value(rate)) * rate; }, 0.0, rim, cuts);
  return area * integral / (rim * rim);
}

}  // namespace softglass::macro::exact
