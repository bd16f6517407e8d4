// Parallel plates (torsional flow): exact torque and normal force.
//
// Plates of radius R a gap h apart; the top one turns at Ω. Without inertia
// v_θ = Ω r z/h is exact for any generalised-Newtonian law: the shear rate
// γ̇(r) = Ω r/h = γ̇_R r/R (γ̇_R = ΩR/h the rim rate) does not depend on z, so
// the only stress τ_θz(r) satisfies ∂τ_θz/∂z = 0, and the cylindrical free rim
// carries no τ_rθ. For Ω > 0 every r > 0 is sheared: no unyielded region. So
//
//     T = 2π ∫₀^R τ(γ̇_R r/R) r² dr = 2πR³ [τ_y/3 + K γ̇_R^n/(n+3)]
//
// for Herschel–Bulkley: macro.md's formula is exact (not a small-gap or
// narrow-rim approximation). It inverts in closed form,
// γ̇_R = ((n+3)(T/(2πR³) − τ_y/3)/K)^{1/n}, no flow for T ≤ 2πR³τ_y/3.
//
// Normal force. With θ the flow, z the gradient and r the vorticity direction,
// N1 = σ_θθ − σ_zz, N2 = σ_zz − σ_rr. The radial balance dσ_rr/dr = (N1 + N2)/r,
// σ_rr(R) = −p_a on the rim, and F = −∫₀^R (σ_zz + p_a) 2πr dr give
//     F = π ∫₀^R (N1 − N2)(γ̇(r)) r dr
//       = πR² [(N1_y − N2_y)/2 + K_N1 γ̇_R^{n_N1}/(n_N1+2) − K_N2 γ̇_R^{n_N2}/(n_N2+2)],
// equivalent to the rheometer relation N1 − N2 = (F/πR²)(2 + d ln F/d ln γ̇_R) at the rim.
#pragma once

#include "macro/material/herschel_bulkley.h"
#include "macro/material/material.h"

namespace softglass::macro::exact {

struct ParallelPlates {
  double radius = 0.025;  ///< R [m]
  double gap = 1e-3;      ///< h [m]
};

/// γ̇_R = Ω R/h [1/s].
double rim_rate(const ParallelPlates& plates, double rotation_rate);

/// T [N m] at Ω > 0 [rad/s] (at Ω = 0 the limit Ω → 0⁺, 2πR³τ_y/3).
double torque(const HerschelBulkley& law, const ParallelPlates& plates, double rotation_rate);

/// Ω [rad/s] under torque T [N m], closed form; 0 for T ≤ 2πR³τ_y/3.
double rotation_rate(const HerschelBulkley& law, const ParallelPlates& plates, double torque);

/// F [N] on the plates at Ω ≥ 0 [rad/s].
double normal_force(const NormalStressLaw& n1, const NormalStressLaw& n2,
                    const ParallelPlates& plates, double rotation_rate);

}  // namespace softglass::macro::exact
