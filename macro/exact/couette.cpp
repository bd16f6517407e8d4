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

}  // namespace

double shear_stress(const CouetteCell& cell, double torque, double r) {
  return torque / (2.0 * std::numbers::pi * cell.length * r * r);
}

double yield_radius(const HerschelBulkley& law, const CouetteCell& cell, double torque) {
  if (law.yield_stress == 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(torque / (2.0 * std::numbers::pi * cell.length * law.yield_stress));
}

double angular_velocity(const HerschelBulkley& law, const CouetteCell& cell, double torque,
                        double r) {
  const double tau_y = law.yield_stress;
  const double tau_lo = std::max(tau_y, shear_stress(cell, torque, cell.outer_radius));
  const double tau_r = shear_stress(cell, torque, r);
  if (tau_r <= tau_lo) return 0.0;
  // In the excess stress e = τ − τ_y (HerschelBulkley::rate_at_excess). A rate
  // that overflows at the upper end makes ω larger than any representable
  // rotation rate: +inf, which the torque's root finding takes as "too high".
  const double e_lo = tau_lo - tau_y, e_r = tau_r - tau_y;
  if (std::isinf(law.rate_at_excess(e_r))) return std::numeric_limits<double>::infinity();
  return 0.5 * numerics::integrate(
                   [&](double e) { return law.rate_at_excess(e) / (tau_y + e); }, e_lo, e_r);
}

double rotation_rate(const HerschelBulkley& law, const CouetteCell& cell, double torque) {
  return angular_velocity(law, cell, torque, cell.inner_radius);
}

double torque(const HerschelBulkley& law, const CouetteCell& cell, double rotation_rate) {
  if (rotation_rate <= 0.0) return torque_at_inner_stress(cell, law.yield_stress);
  const double ratio = cell.outer_radius / cell.inner_radius;
  const double s = law.stress(rotation_rate / std::log(ratio));
  const double tau_1 = numerics::solve_increasing(
      [&](double tau) {
        return exact::rotation_rate(law, cell, torque_at_inner_stress(cell, tau)) - rotation_rate;
      },
      s, ratio * ratio * s, "Couette torque");
  return torque_at_inner_stress(cell, tau_1);
}

}  // namespace softglass::macro::exact
