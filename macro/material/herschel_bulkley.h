// The Herschel–Bulkley law, the shear law of every macro scene.
//
// A yield-stress material flows only where the magnitude of its deviatoric
// stress exceeds the yield stress τ_y; there
//
//     τ = τ_y + K γ̇ⁿ ,
//
// with consistency K and flow index n (soft glasses: n ≈ 1/2). The other laws of
// the material file are special cases: Bingham is n = 1 (K the plastic
// viscosity), the power law τ_y = 0, Newtonian both (K = μ). One type covers
// them all, so that every formula is written once and the special cases are
// tests of it. In a general flow the scalars are the invariants
// γ̇ = √(2 D:D) and |τ| = √(½ τ:τ), and the law reads τ = 2η(γ̇) D where yielded
// (docs/macro.md, "Conventions").
//
// Below the yield stress the material is rigid, γ̇ = 0 for any |τ| ≤ τ_y: the law
// is a graph, not a function, at γ̇ = 0. The members below work with its
// single-valued pieces: the stress of a flowing material τ(γ̇), γ̇ > 0, and the
// rate at a given stress γ̇(τ), τ ≥ 0 (the inverse flow curve, zero below τ_y),
// which every exact solution of a rheometer or channel integrates.
//
// The finite-element solvers see it through the interface of shear_law.h
// (shear_law() below); the closed forms of exact/ use it directly.
#pragma once

#include <memory>

namespace softglass::macro {

class ShearLaw;

struct HerschelBulkley {
  double yield_stress = 0.0;  ///< τ_y [Pa], ≥ 0
  double consistency = 1.0;   ///< K [Pa sⁿ], > 0
  double flow_index = 1.0;    ///< n [1], 0 < n ≤ 2

  /// τ(γ̇) = τ_y + K γ̇ⁿ for γ̇ ≥ 0; at γ̇ = 0 its limit from above, τ_y.
  double stress(double rate) const;

  /// γ̇(τ) = ((τ − τ_y)/K)^{1/n} for τ > τ_y and 0 for 0 ≤ τ ≤ τ_y.
  double rate(double stress) const;

  /// γ̇ at τ = τ_y + excess, excess ≥ 0: (excess/K)^{1/n}. Integrals over a
  /// thinly yielded layer (τ − τ_y ≪ τ_y) take the excess as their variable, so
  /// that it is not formed as the difference of two nearly equal stresses,
  /// which would leave it only a few significant digits.
  double rate_at_excess(double excess) const;

  /// The secant viscosity η(γ̇) = τ(γ̇)/γ̇ = τ_y/γ̇ + K γ̇^{n−1}, γ̇ > 0. It is
  /// unbounded as γ̇ → 0 when τ_y > 0 or n < 1 (+inf at γ̇ = 0): solvers need a
  /// regularised law (regularised_law.h) or an augmented Lagrangian.
  double viscosity(double rate) const;

  /// The local step of augmented-Lagrangian (ALG2-type) solvers: the rate s ≥ 0
  /// minimising φ(s) + ½ r s² − χ s, φ(s) = τ_y s + K s^{n+1}/(n+1) the
  /// dissipation potential, for a trial stress χ ≥ 0 and penalty r ≥ 0. That is
  ///     s = 0 if χ ≤ τ_y,   else  τ_y + K sⁿ + r s = χ,
  /// solved in closed form for n = 1 and by TOMS 748 otherwise (relative
  /// accuracy numerics::kRootTolerance). r = 0 gives the inverse flow curve γ̇(χ).
  double proximal_rate(double trial_stress, double penalty) const;
};

/// The law as the finite-element solvers see it (shear_law.h).
std::shared_ptr<const ShearLaw> shear_law(const HerschelBulkley& law);

/// τ = τ_y + μ_p γ̇.
HerschelBulkley bingham(double yield_stress, double plastic_viscosity);
/// τ = K γ̇ⁿ.
HerschelBulkley power_law(double consistency, double flow_index);
/// τ = μ γ̇.
HerschelBulkley newtonian(double viscosity);

}  // namespace softglass::macro
