// Parallel plates (torsional flow): exact torque and normal force.
//
// Plates of radius R a gap h apart; the top one turns at Ω. Without inertia
// v_θ = Ω r z/h is exact for any generalised-Newtonian law: the shear rate
// γ̇(r) = Ω r/h = γ̇_R r/R (γ̇_R = ΩR/h the rim rate) does not depend on z, so
// the only stress τ_θz(r) satisfies ∂τ_θz/∂z = 0, and the cylindrical free rim
// carries no τ_rθ. For Ω > 0 every r > 0 is sheared: no unyielded region. So
//
//     T = 2π ∫₀^R τ(γ̇_R r/R) r² dr = 2πR³ [τ_y/3 + γ̇_R⁻³ ∫₀^{γ̇_R} Δ(γ̇) γ̇² dγ̇],
//
// Δ = τ − τ_y, evaluated by quadrature for any law (split at a tabulated
// law's nodes); for Herschel–Bulkley it is 2πR³ [τ_y/3 + K γ̇_R^n/(n+3)],
// macro.md's formula, exact (not a small-gap or narrow-rim approximation):
// that is the test. The inverse solves T(γ̇_R) = T inside a bracket that needs
// no search: Δ increases, so γ̇_R⁻³∫₀^{γ̇_R} Δ γ̇² dγ̇ lies between
// (7/24) Δ(γ̇_R/2) and Δ(γ̇_R)/3, and with E = T/(2πR³) − τ_y/3 the root lies in
// [γ̇(3E), 2 γ̇(24E/7)], γ̇(·) the law's rate at an excess stress. No flow for
// T ≤ 2πR³τ_y/3.
//
// Normal force. With θ the flow, z the gradient and r the vorticity direction,
// N1 = σ_θθ − σ_zz, N2 = σ_zz − σ_rr. The radial balance dσ_rr/dr = (N1 + N2)/r,
// σ_rr(R) = −p_a on the rim, and F = −∫₀^R (σ_zz + p_a) 2πr dr give
//     F = π ∫₀^R (N1 − N2)(γ̇(r)) r dr
//       = πR² γ̇_R⁻² ∫₀^{γ̇_R} (N1 − N2)(γ̇) γ̇ dγ̇   (quadrature; for power laws
//       = πR² [(N1_y − N2_y)/2 + K_N1 γ̇_R^{n_N1}/(n_N1+2) − K_N2 γ̇_R^{n_N2}/(n_N2+2)]),
// equivalent to the rheometer relation N1 − N2 = (F/πR²)(2 + d ln F/d ln γ̇_R) at the rim.
#pragma once

#include "macro/exact/law_ref.h"
#include "macro/material/normal_stress.h"

namespace softglass::macro::exact {

struct ParallelPlates {
  double radius = 0.025;  ///< R [m]
  double gap = 1e-3;      ///< h [m]
};

/// γ̇_R = Ω R/h [1/s].
double rim_rate(const ParallelPlates& plates, double rotation_rate);

/// T [N m] at Ω > 0 [rad/s] (at Ω = 0 the limit Ω → 0⁺, 2πR³τ_y/3).
double torque(LawRef law, const ParallelPlates& plates, double rotation_rate);

/// Ω [rad/s] under torque T [N m]; 0 for T ≤ 2πR³τ_y/3.
double rotation_rate(LawRef law, const ParallelPlates& plates, double torque);

/// F [N] on the plates at Ω ≥ 0 [rad/s].
double normal_force(const NormalStressCurve& n1, const NormalStressCurve& n2,
                    const ParallelPlates& plates, double rotation_rate);

}  // namespace softglass::macro::exact
