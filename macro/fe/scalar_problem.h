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
//
// Wall slip. On a smooth wall Γ_s the material slides: the wall no longer
// fixes u, but resists the slip velocity V_s (the velocity of the material at
// the wall relative to the wall) with a wall shear stress σ_w(V_s) given by a
// slip law (material/slip_law.h), whose potential D(V) = ∫₀^V σ_w is convex.
// The wall dissipates σ_w V_s per unit area, so J gains the wall's potential,
//
//     J(u) = ∫ [ Ψ(γ̇) − f u ] ρ dx + ∫_Γs D(V_s) ρ ds,     V_s = s (u − u_w),
//
// with u_w the wall's value of the unknown (0 on a wall at rest, Ω on a
// rotor). The scaling, scene by scene: the outputs are c ∫ ρ (·) over the
// section (c the measure factor, SectionWeights), and the wall's area element
// is likewise c ρ ds — 2πL · r for a Couette cylinder at r (ds the point
// measure of a 1D section), 2π r dl on a meridian section's wall curve, 2 per
// unit width for the two walls of a half channel. The slip velocity is the
// difference of tangential velocities: u − u_w itself for the channel and
// pipe (s = 1), and for the swirling flows r ω − r Ω = r (ω − Ω) (s = r),
// because the unknown there is the angular velocity. So c ∫_Γs D(V_s) ρ ds is
// the wall's dissipation potential in every scene.
//
// Its first variation adds ∫_Γs ρ s σ_w(V_s) v ds to the weak form: the
// natural condition becomes the nonlinear Robin condition
//
//     ρ s² η ∂u/∂n + ρ s σ_w(V_s) = 0,   i.e.   τ_n = η s ∂u/∂n = −σ_w(V_s),
//
// the wall's traction opposing the slip: for the swirl, ρ s² = r³ and ρ s = r²
// give η r ∂ω/∂n = −σ_w, the shear stress τ_nθ = η r ∂ω/∂n; for the channel
// η ∂u/∂n = −σ_w(u) at y = H. The second variation, Newton's boundary matrix,
// is ∫_Γs ρ s² σ_w'(V_s) δu v ds, positive: J stays convex, and strictly so
// even where no wall fixes u (a Couette cell slipping on both cylinders).
// Testing the weak form with u itself gives the power balance: the power the
// moving walls put in equals c ∫ ρ τ γ̇ dx + c ∫_Γs ρ σ_w V_s ds, bulk plus
// wall dissipation, which is how the torque is computed (scenes/reduced_scene).
#pragma once

#include <deal.II/base/types.h>

#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "macro/material/slip_law.h"

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
  /// The walls' values of u on boundary ids (walls at rest 0, rotor Ω): the
  /// Dirichlet data of no-slip walls, u_w of slip walls (WallSlip); ids not
  /// listed carry the natural (free-surface or symmetry) condition.
  std::map<dealii::types::boundary_id, double> boundary_values;
  /// The shear rate that sets the scale of the regularisation, ε = ε_rel γ̇_c.
  double characteristic_rate = 1.0;
};

/// The walls that slip, and how: the boundary ids of Drive::boundary_values
/// whose value is the wall's u_w rather than the material's.
struct WallSlip {
  std::shared_ptr<const SlipLaw> law;  ///< null where no wall slips
  std::set<dealii::types::boundary_id> walls;
  /// The slip law is regularised at the velocity scale ε_V = ε · length, ε the
  /// bulk's rate scale (so that the continuation in ε relaxes both): the
  /// length over which the scene shears, its gap.
  double length = 1.0;  ///< [m]

  bool any() const { return law && !walls.empty(); }
};

}  // namespace softglass::macro::fe
