// Couette flow between coaxial cylinders: the exact torque–rotation relation of
// a Herschel–Bulkley material, partially or fully yielded.
//
// The inner cylinder (radius R1) turns at Ω, the outer one (R2) is fixed; the
// gap is filled over a length L, end effects neglected. The swirl v_θ(r) = r ω(r)
// is the only velocity. The θ-momentum balance (1/r²) d(r² τ_rθ)/dr = 0 makes
// the torque T carried through every cylinder r the same, so
//
//     τ(r) = T / (2π L r²),    τ1 = τ(R1),  τ2 = τ(R2),
//
// whatever the law. The shear rate is γ̇ = −r dω/dr, the inverse flow curve of
// τ(r); with ω(R2) = 0 and dr/r = −dτ/(2τ),
//
//     ω(r) = ∫_r^{R2} γ̇(τ(s)) ds/s = ½ ∫_{τ_lo}^{τ(r)} γ̇(τ)/τ dτ,   τ_lo = max(τ_y, τ2),
//     Ω = ω(R1).
//
// The integrand vanishes below τ_y: beyond the yield radius
// R_c = √(T/(2π L τ_y)), where τ = τ_y, the material rests with the outer wall.
// The cell is partially yielded when R1 < R_c < R2, fully yielded for R_c ≥ R2,
// and at rest for R_c ≤ R1 (T below the static yield torque 2π L R1² τ_y).
//
// For n = 1/2 the integral is elementary (macro.md): γ̇ = (τ − τ_y)²/K² and
//     Ω = [F(τ1) − F(τ_lo)]/(2K²),   F(τ) = τ²/2 − 2τ_y τ + τ_y² ln τ;
// for Bingham Ω = [τ1 − τ_lo − τ_y ln(τ1/τ_lo)]/(2μ); for a power law
// Ω = n (τ1^{1/n} − τ2^{1/n})/(2K^{1/n}); Newtonian (Margules)
// Ω = T (1/R1² − 1/R2²)/(4π μ L). Those are the tests; the code integrates
// numerically for every n (numerics/quadrature.h, relative error ~1e-14).
//
// The inverse T(Ω) solves Ω(T) = Ω for τ1 by TOMS 748 inside a bracket that
// needs no search. Since γ̇(τ)/τ is bounded on [τ_lo, τ1] by γ̇(τ1)/τ above and
// γ̇(τ2)/τ below (for τ2 ≥ τ_y), and ½∫_{τ2}^{τ1} dτ/τ = ln(R2/R1),
//     γ̇(τ2) ln(R2/R1) ≤ Ω(τ1) ≤ γ̇(τ1) ln(R2/R1);
// with s = τ(Ω/ln(R2/R1)) from the flow curve, τ1 = s gives Ω(τ1) ≤ Ω and
// τ1 = (R2/R1)² s gives Ω(τ1) ≥ Ω: the root lies in [s, (R2/R1)² s].
//
// Wall slip. If the bob or the cup slips by a law V_s(σ_w) (slip_law.h), the
// material at each cylinder moves relative to it at the slip velocity of the
// wall stress there, τ1 at the bob and τ2 at the cup (the balance above holds
// whatever the walls do), and the material lags the bob and leads the cup.
// Adding the angular velocities of the two slip layers, V/r,
//
//     ω(r) = V_s,2(τ2)/R2 + ½ ∫_{τ_lo}^{τ(r)} γ̇(τ)/τ dτ,
//     Ω    = V_s,1(τ1)/R1 + V_s,2(τ2)/R2 + ½ ∫_{τ_lo}^{τ1} γ̇(τ)/τ dτ,
//
// which still increases with T, continuously from 0: without a slip yield
// stress a slipping cell turns under any torque, the unyielded material
// beyond R_c rotating rigidly at V_s,2/R2 (a partially yielded gap), or all of
// it when τ1 ≤ τ_y. The bracket of T(Ω) widens: at the root one of the three
// terms is at least Ω/3, so τ1 is at least the smallest of s taken at Ω/3,
// σ_w,1(R1 Ω/3) and (R2/R1)² σ_w,2(R2 Ω/3); (R2/R1)² s stays an upper bound,
// the slip terms being positive.
#pragma once

#include "macro/exact/law_ref.h"
#include "macro/material/slip_law.h"

namespace softglass::macro::exact {

struct CouetteCell {
  double inner_radius = 1.0;  ///< R1 [m], the rotating bob
  double outer_radius = 2.0;  ///< R2 [m] > R1, the fixed cup
  double length = 1.0;        ///< L [m], the wetted length
};

/// The cylinders' slip laws; null: no slip (the default).
struct CouetteWalls {
  const SlipLaw* inner = nullptr;  ///< the bob
  const SlipLaw* outer = nullptr;  ///< the cup
};

/// τ(r) = T/(2π L r²) [Pa].
double shear_stress(const CouetteCell& cell, double torque, double r);

/// R_c = √(T/(2π L τ_y)) [m], +inf for τ_y = 0. Compare with R1 and R2.
double yield_radius(LawRef law, const CouetteCell& cell, double torque);

/// ω(r) = v_θ/r [rad/s] of the material at R1 ≤ r ≤ R2 under torque T [N m].
double angular_velocity(LawRef law, const CouetteCell& cell, double torque,
                        double r, const CouetteWalls& walls = {});

/// Ω [rad/s], the bob's, under torque T [N m]; without slip 0 below the static
/// yield torque.
double rotation_rate(LawRef law, const CouetteCell& cell, double torque,
                     const CouetteWalls& walls = {});

/// T [N m] at rotation rate Ω ≥ 0 [rad/s], the inverse of rotation_rate to
/// ~1e-13 relative; at Ω = 0 the limit Ω → 0⁺: the static yield torque
/// 2π L R1² τ_y without slip, the smaller of it and the torques at which
/// the walls begin to slip (their slip yield stresses) with slip.
double torque(LawRef law, const CouetteCell& cell, double rotation_rate,
              const CouetteWalls& walls = {});

}  // namespace softglass::macro::exact
