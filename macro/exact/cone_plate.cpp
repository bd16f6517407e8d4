#include "macro/exact/cone_plate.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "macro/numerics/quadrature.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro::exact {

namespace {

// T = 2πR³τ_p/3 and back.
double plate_stress(const ConePlate& cone, double torque) {
  return 3.0 * torque / (2.0 * std::numbers::pi * std::pow(cone.radius, 3));
}
double torque_at_plate_stress(const ConePlate& cone, double tau_p) {
  return 2.0 * std::numbers::pi * std::pow(cone.radius, 3) * tau_p / 3.0;
}

}  // namespace

double yield_angle(LawRef law, const ConePlate& cone, double torque) {
  const double tau_p = plate_stress(cone, torque);
  return tau_p >= law->yield_stress() ? 0.0 : std::acos(std::sqrt(tau_p / law->yield_stress()));
}

double angular_velocity(LawRef law, const ConePlate& cone, double torque,
                        double psi) {
  const double tau_p = plate_stress(cone, torque), psi_y = yield_angle(law, cone, torque);
  if (psi <= psi_y) return 0.0;
  // τ = τ_p/cos²ψ passes the law's breakpoints τ_y + Δ_i at ψ_i = acos √(τ_p/τ_i).
  std::vector<double> cuts;
  for (const double excess : law->excess_breakpoints()) {
    const double tau = law->yield_stress() + excess;
    if (tau > tau_p) cuts.push_back(std::acos(std::sqrt(tau_p / tau)));
  }
  return numerics::integrate(
      [&](double p) {
        const double c = std::cos(p);
        return law->rate(tau_p / (c * c)) / c;
      },
      psi_y, psi, cuts);
}

double rotation_rate(LawRef law, const ConePlate& cone, double torque) {
  return angular_velocity(law, cone, torque, cone.angle);
}

double torque(LawRef law, const ConePlate& cone, double rotation_rate) {
  const double beta = cone.angle, cos_beta = std::cos(beta);
  if (rotation_rate <= 0.0) {
    return torque_at_plate_stress(cone, law->yield_stress() * cos_beta * cos_beta);
  }
  const double lo = cos_beta * cos_beta * law->stress(rotation_rate * cos_beta / beta);
  const double hi = law->stress(rotation_rate / beta);
  const double tau_p = numerics::solve_increasing(
      [&](double tau) {
        return exact::rotation_rate(law, cone, torque_at_plate_stress(cone, tau)) - rotation_rate;
      },
      lo, hi, "cone-plate torque");
  return torque_at_plate_stress(cone, tau_p);
}

double small_angle_torque(LawRef law, const ConePlate& cone,
                          double rotation_rate) {
  return torque_at_plate_stress(cone, law->stress(rotation_rate / cone.angle));
}

double normal_force(const NormalStressCurve& n1, const ConePlate& cone, double rotation_rate) {
  return 0.5 * std::numbers::pi * cone.radius * cone.radius * n1.value(rotation_rate / cone.angle);
}

}  // namespace softglass::macro::exact
