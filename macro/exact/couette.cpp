#include "macro/exact/couette.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "macro/numerics/quadrature.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro::exact {

namespace {

double torque_at_inner_stress(const CouetteCell& cell, double tau_1) {
  const double R1 = cell.inner_radius;
  return 2.0 * std::numbers::pi * cell.length * R1 * R1 * tau_1;
}

// The angular velocity V_s(σ_w)/r of a slip layer at radius r (0 without slip).
double slip_rotation(const SlipLaw* wall, const CouetteCell& cell, double torque, double r) {
  return wall ? wall->velocity(shear_stress(cell, torque, r)) / r : 0.0;
}

}  // namespace

double shear_stress(const CouetteCell& cell, double torque, double r) {
  return torque / (2.0 * std::numbers::pi * cell.length * r * r);
}

double yield_radius(LawRef law, const CouetteCell& cell, double torque) {
  if (law->yield_stress() == 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(torque / (2.0 * std::numbers::pi * cell.length * law->yield_stress()));
}

double angular_velocity(LawRef law, const CouetteCell& cell, double torque,
                        double r, const CouetteWalls& walls) {
  const double cup = slip_rotation(walls.outer, cell, torque, cell.outer_radius);
  const double tau_y = law->yield_stress();
  const double tau_lo = std::max(tau_y, shear_stress(cell, torque, cell.outer_radius));
  const double tau_r = shear_stress(cell, torque, r);
  if (tau_r <= tau_lo) return cup;
  // In the excess stress e = τ − τ_y (ShearLaw::rate_at_excess). A rate
  // that overflows at the upper end makes ω larger than any representable
  // rotation rate: +inf, which the torque's root finding takes as "too high".
  const double e_lo = tau_lo - tau_y, e_r = tau_r - tau_y;
  if (std::isinf(law->rate_at_excess(e_r))) return std::numeric_limits<double>::infinity();
  return cup + 0.5 * numerics::integrate(
                         [&](double e) { return law->rate_at_excess(e) / (tau_y + e); }, e_lo, e_r,
                         law->excess_breakpoints());
}

double rotation_rate(LawRef law, const CouetteCell& cell, double torque,
                     const CouetteWalls& walls) {
  return angular_velocity(law, cell, torque, cell.inner_radius, walls) +
         slip_rotation(walls.inner, cell, torque, cell.inner_radius);
}

double torque(LawRef law, const CouetteCell& cell, double rotation_rate,
              const CouetteWalls& walls) {
  const double ratio = cell.outer_radius / cell.inner_radius;
  // A slip wall's stress at the bob, σ_w(V) at the cup scaled by (R2/R1)².
  const auto inner_stress = [&](const SlipLaw* wall, double scale, double velocity) {
    return wall ? scale * wall->stress(velocity) : std::numeric_limits<double>::infinity();
  };
  if (rotation_rate <= 0.0) {
    return torque_at_inner_stress(
        cell, std::min({law->yield_stress(), inner_stress(walls.inner, 1.0, 0.0),
                        inner_stress(walls.outer, ratio * ratio, 0.0)}));
  }
  const double s = law->stress(rotation_rate / std::log(ratio));
  const double third = rotation_rate / 3.0;
  const double lo =
      std::min({walls.inner || walls.outer ? law->stress(third / std::log(ratio)) : s,
                inner_stress(walls.inner, 1.0, cell.inner_radius * third),
                inner_stress(walls.outer, ratio * ratio, cell.outer_radius * third)});
  const double tau_1 = numerics::solve_increasing(
      [&](double tau) {
        return exact::rotation_rate(law, cell, torque_at_inner_stress(cell, tau), walls) -
               rotation_rate;
      },
      lo, ratio * ratio * s, "Couette torque");
  return torque_at_inner_stress(cell, tau_1);
}

}  // namespace softglass::macro::exact
