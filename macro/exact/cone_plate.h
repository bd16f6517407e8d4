// Cone and plate: the exact torque–rotation relation for any cone angle, its
// small-angle approximation, and the normal force.
//
// Spherical coordinates (r, θ, φ) about the axis; ψ = π/2 − θ is the angle
// above the plate. The plate (ψ = 0) is fixed, the cone surface ψ = β turns at
// Ω. Each cone ψ = const turns rigidly, v_φ = r cos ψ ω(ψ), so the shear rate is
// γ̇ = cos ψ |dω/dψ| and the only stress is τ = τ_θφ(ψ). The φ-momentum balance
// d(sin²θ τ_θφ)/dθ = 0 gives
//
//     τ(ψ) = τ_p / cos²ψ,     τ_p the stress on the plate,
//
// least on the plate, largest on the cone. Every sphere r = const is free of
// traction (τ_rφ = 0), so this flow is exact for a sample whose free rim is the
// sphere r = R; the torque on plate (and cone) is T = ∫₀^R τ_p r 2πr dr =
// 2πR³τ_p/3. Integrating γ̇ from the plate,
//
//     ω(ψ) = ∫₀^ψ γ̇(τ_p/cos²ψ')/cos ψ' dψ',      Ω = ω(β),
//
// which is macro.md's Ω = ∫_{π/2−β}^{π/2} γ̇(τ_p/sin²θ)/sin θ dθ. The integrand
// vanishes where τ ≤ τ_y: if τ_p < τ_y, a layer ψ < ψ_y = arccos √(τ_p/τ_y) rests
// on the plate, and nothing flows once ψ_y ≥ β, i.e. τ_p ≤ τ_y cos²β. The
// integral runs from ψ_y, so the quadrature sees the yield point at an end.
//
// Small angles: γ̇ → Ω/β uniform and T → (2πR³/3) τ(Ω/β), the standard
// rheometer formula; its relative error is O(β²). Newtonian:
// T_exact/T_small = β / ∫₀^β sec³ψ dψ ≈ 1 − β²/2, 0.999391 at β = 2° (macro.md).
// The normal force on the plate in the small-angle limit is F = πR² N1(Ω/β)/2
// (N2 does not enter).
//
// The inverse T(Ω) solves Ω(τ_p) = Ω by TOMS 748 in a bracket found without a
// search. Since 1 ≤ 1/cos ψ ≤ 1/cos β and τ_p ≤ τ(ψ) ≤ τ_p/cos²β on [0, β],
//     β γ̇(τ_p) ≤ Ω(τ_p) ≤ β γ̇(τ_p/cos²β)/cos β,
// so τ_p = cos²β τ(Ω cos β/β) gives Ω(τ_p) ≤ Ω and τ_p = τ(Ω/β) gives Ω(τ_p) ≥ Ω.
#pragma once

#include "macro/exact/law_ref.h"
#include "macro/material/normal_stress.h"

namespace softglass::macro::exact {

struct ConePlate {
  double radius = 0.025;  ///< R [m]
  double angle = 0.0349;  ///< β [rad], the gap angle between cone and plate
};

/// ψ_y [rad]: the material rests on the plate for ψ < ψ_y (0 if τ_p ≥ τ_y); no
/// flow at all if ψ_y ≥ β.
double yield_angle(LawRef law, const ConePlate& cone, double torque);

/// ω(ψ) [rad/s] for 0 ≤ ψ ≤ β under torque T [N m], exact.
double angular_velocity(LawRef law, const ConePlate& cone, double torque,
                        double psi);

/// Ω = ω(β) [rad/s] under torque T [N m], exact.
double rotation_rate(LawRef law, const ConePlate& cone, double torque);

/// T [N m] at Ω ≥ 0 [rad/s], exact, the inverse of rotation_rate (~1e-13
/// relative); at Ω = 0 the limit Ω → 0⁺, 2πR³τ_y cos²β/3.
double torque(LawRef law, const ConePlate& cone, double rotation_rate);

/// T = (2πR³/3) τ(Ω/β) [N m], the small-angle approximation.
double small_angle_torque(LawRef law, const ConePlate& cone,
                          double rotation_rate);

/// F = πR² N1(Ω/β)/2 [N], the small-angle normal force on the plate.
double normal_force(const NormalStressCurve& n1, const ConePlate& cone, double rotation_rate);

}  // namespace softglass::macro::exact
