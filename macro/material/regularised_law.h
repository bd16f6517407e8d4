// Regularised viscosities, for the regularised solvers: the yield term of a
// constitutive law (shear_law.h) made smooth, one regularisation per file.
//
// The viscosity η(γ̇) = τ_y/γ̇ + K γ̇^{n−1} is infinite wherever the material is
// rigid, so the flow problem −∇·(2η(γ̇)D) + ∇p = f cannot be solved as it
// stands. A regularised law replaces η by a smooth, positive, bounded η_ε that
// tends to η at every γ̇ > 0 as the rate scale ε → 0. The "rigid" regions then
// creep at rates of order ε, and the problem is an ordinary generalised-
// Newtonian one, solved by Picard or Newton iteration. Every regularised law is
//
//     η_ε(γ̇) = η_y,ε(γ̇) + K (γ̇² + ε²)^{(n−1)/2},
//
// a regularised yield term, one per file —
//
//     papanastasiou        τ_y (1 − e^{−mγ̇})/γ̇,   m = 1/ε     (Papanastasiou 1987)
//     bercovier-engelman   τ_y / √(γ̇² + ε²)                  (Bercovier & Engelman 1980)
//
// — plus the law's own viscous part regularised at the same ε
// (ShearLaw::regularised_flow_viscosity; Herschel–Bulkley's power-law term
// K (γ̇² + ε²)^{(n−1)/2}, exactly K for n = 1). At γ̇ = 0:
// η_ε = τ_y m + K ε^{n−1} (Papanastasiou), τ_y/ε + K ε^{n−1} (Bercovier–Engelman).
//
// Accuracy. At fixed γ̇ > 0 the Bercovier–Engelman error is O(ε²)
// (−ε²[τ_y/γ̇³ + (1−n)Kγ̇^{n−3}]/2); Papanastasiou's yield term is
// exponentially close (−τ_y e^{−mγ̇}/γ̇), so its error is the power-law term's,
// O(ε²) = O(m⁻²), and exponentially small for n = 1. Where it counts — near the
// yield surfaces, where γ̇ ~ ε — the error of a flow is larger: the flow rate
// of an HB channel converges like O(ε) (O(1/m)) for both (tests/macro).
//
// Newton linearisation. With the tangent τ'(γ̇) = dτ/dγ̇ = η + γ̇ dη/dγ̇ > 0:
//   scalar problems (flux q = η(|g|) g, g = ∇w or the swirl gradient, γ̇ = |g|):
//       ∂q/∂g = η (I − n⊗n) + τ' n⊗n,    n = g/|g|;
//   tensor problems (τ = 2η D, γ̇ = √(2D:D)):
//       ∂τ/∂D = 2[η (𝕀 − N⊗N) + τ' N⊗N],  N = √2 D/γ̇ (N:N = 1).
// Both are positive definite. At γ̇ = 0 the direction n is undefined, but there
// γ̇ dη/dγ̇ = 0 and τ' = η, so the tangent is η I (2η𝕀): take n = 0 (N = 0).
//
// The regularisations, one file each in regularisations/, are registered
// (common/registry.h) in regularisations/registered_regularisations.h, one
// line each; the parameter files' allowed values of `regularisation` are the
// registry's names.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "common/registry.h"
#include "macro/material/shear_law.h"

namespace softglass::macro {

class RegularisedLaw {
 public:
  virtual ~RegularisedLaw() = default;

  /// The registry name: papanastasiou, bercovier-engelman.
  virtual std::string name() const = 0;

  /// η_ε(γ̇) and dη_ε/dγ̇ for γ̇ ≥ 0; η_ε > 0 and both finite everywhere.
  Viscosity viscosity(double rate) const;

  /// τ_ε(γ̇) = η_ε(γ̇) γ̇: zero at rest, strictly increasing.
  double stress(double rate) const;

  /// τ_ε'(γ̇) = η_ε + γ̇ dη_ε/dγ̇ > 0, the Newton tangent along the flow.
  double tangent(double rate) const;

  /// The inverse of stress(): γ̇ ≥ 0 with τ_ε(γ̇) = τ, for τ ≥ 0 (TOMS 748,
  /// relative accuracy numerics::kRootTolerance).
  double rate(double stress) const;

  /// The law being regularised.
  const ShearLaw& law() const { return law_; }
  /// ε [1/s]: the rate below which the material creeps instead of resting.
  double rate_scale() const { return rate_scale_; }

 protected:
  /// `law` must outlive the regularised law.
  RegularisedLaw(const ShearLaw& law, double rate_scale);

  /// The regularised yield term η_y,ε(γ̇) ≈ τ_y/γ̇ and its derivative.
  virtual Viscosity yield_term(double rate) const = 0;

 private:
  const ShearLaw& law_;
  double rate_scale_;
};

/// What a regularisation is made from: the law and ε [1/s].
struct RegularisationSpec {
  const ShearLaw& law;
  double rate_scale;
};
using RegularisationEntry = ComponentEntry<RegularisedLaw, RegularisationSpec>;

/// Every regularisation (regularisations/registered_regularisations.h).
const Registry<RegularisationEntry>& regularisations();

/// The regularisation called `name` of `law` (which must outlive it) with rate
/// scale ε = `rate_scale` (for Papanastasiou m = 1/ε). InputError for an
/// unknown name or ε not > 0.
std::unique_ptr<RegularisedLaw> make_regularised_law(std::string_view name, const ShearLaw& law,
                                                     double rate_scale);

}  // namespace softglass::macro
