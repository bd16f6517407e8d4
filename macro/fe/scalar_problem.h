// The reduced scalar problem behind every unidirectional or swirling scene.
//
// Without inertia, the flows of a channel, a pipe, a duct, a Couette cell, a
// cone and plate and parallel plates each have one velocity component u on a
// 1D or 2D section, and the momentum balance is the Euler–Lagrange equation of
// one convex functional (the dissipation minus the work of the driving force),
//
//     J(u) = ∫ [ Ψ(γ̇) − f u ] ρ dx,      γ̇ = s(x) |∇u|,      Ψ(γ̇) = ∫₀^γ̇ τ(g) dg,
//
// whose weak form is
//
//     ∫ ρ s² η(γ̇) ∇u·∇v dx = ∫ ρ f v dx      for all v vanishing on the walls.
//
// ρ is the volume weight of the section (r on an axisymmetric section, 1 on a
// plane one) and s converts the gradient of the unknown into the shear rate:
//
//   scene                       x          u                   ρ    s    f
//   plane channel (half)        y          u_x                 1    1    G = −dp/dx
//   pipe                        r          u_z                 r    1    G
//   duct of any section         (x, y)     u_z                 1    1    G
//   Couette, cone–plate, plates r or (r,z) ω = u_θ/r            r    r    0
//
// For the swirling flows the unknown is the angular velocity ω rather than u_θ:
// the shear rate of a swirl is γ̇ = r|∇ω| (the rotation of a rigid body has
// ∇ω = 0), so rigid regions and the Dirichlet data (ω = Ω on the rotor) are
// exact constants, and the axis needs no boundary condition (ρ s² = r³ vanishes
// there). The natural boundary condition of the weak form, ρ s² η ∂u/∂n = 0, is
// the traction-free condition of a symmetry plane (channel centre) or of a free
// surface (rim, meniscus).
#pragma once

#include <deal.II/base/types.h>

#include <cmath>

#include <map>
#include <string>

namespace softglass::macro::fe {

/// How the section is weighted: ρ = r^radial_weight, s = r^rate_radius_power
/// with r = x[0] (the first coordinate is the radius on axisymmetric sections).
struct SectionWeights {
  int radial_weight = 0;      ///< 0 plane, 1 axisymmetric
  int rate_radius_power = 0;  ///< 0 for u = velocity, 1 for u = angular velocity
  /// The outputs are integrals over the whole body: 2 for a half channel
  /// (symmetry), 2π for a full revolution, 2πL per length L...
  double measure_factor = 1.0;

  /// ρ and s at a point whose first coordinate is r.
  double rho(double r) const { return power(r, radial_weight); }
  double s(double r) const { return power(r, rate_radius_power); }

 private:
  static double power(double r, int k) { return k == 0 ? 1.0 : (k == 1 ? r : std::pow(r, k)); }
};

/// The driving of one operating point.
struct Drive {
  double source = 0.0;  ///< f [Pa/m]: the pressure gradient of pressure-driven flows
  /// Dirichlet values of u on boundary ids (no-slip walls 0, rotor Ω); ids not
  /// listed carry the natural (free-surface or symmetry) condition.
  std::map<dealii::types::boundary_id, double> boundary_values;
  /// The shear rate that sets the scale of the regularisation, ε = ε_rel γ̇_c.
  double characteristic_rate = 1.0;
};

}  // namespace softglass::macro::fe
