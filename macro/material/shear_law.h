// The constitutive law of the finite-element solvers: what they need to know
// of a material's shear behaviour, and nothing of its form.
//
// A generalised-Newtonian material with (possibly) a yield stress: rigid where
// the stress magnitude |τ| = √(½ τ:τ) is at most τ_y, elsewhere τ = 2η(γ̇)D with
// γ̇ = √(2D:D) (docs/macro.md, "Conventions"). The solvers use
//   - the yield stress, to tell yielded from rigid material (outputs, the
//     cells a yield surface crosses);
//   - τ(γ̇), η(γ̇) and γ̇(τ): stresses, the viscosity scale of a scene, rate
//     scales;
//   - the viscous part of η regularised at a rate scale ε, with its
//     derivative: the regularised laws (regularised_law.h) add it to their
//     regularised yield term, and Newton linearises the sum;
//   - the proximal step of the augmented-Lagrangian method (ALG2).
// Herschel–Bulkley (herschel_bulkley.h) is the law every scene uses today; a
// new law (a slip law, a thixotropic or a tabulated one) is a new file with a
// class implementing this interface.
#pragma once

#include <string>

namespace softglass::macro {

/// η and dη/dγ̇ at one shear rate.
struct Viscosity {
  double value = 0.0;       ///< η [Pa s]
  double derivative = 0.0;  ///< dη/dγ̇ [Pa s²]
};

class ShearLaw {
 public:
  virtual ~ShearLaw() = default;

  virtual std::string name() const = 0;

  /// τ_y [Pa], ≥ 0: the material is rigid where |τ| ≤ τ_y.
  virtual double yield_stress() const = 0;

  /// τ(γ̇) of the flowing material for γ̇ ≥ 0 (its limit τ_y at γ̇ = 0).
  virtual double stress(double rate) const = 0;

  /// The secant viscosity τ(γ̇)/γ̇ for γ̇ > 0.
  virtual double viscosity(double rate) const = 0;

  /// The inverse flow curve γ̇(τ) for τ ≥ 0: zero up to τ_y.
  virtual double rate(double stress) const = 0;

  /// ALG2's local step: the rate s ≥ 0 minimising φ(s) + ½ r s² − χ s, φ the
  /// dissipation potential, for a trial stress χ ≥ 0 and penalty r ≥ 0.
  virtual double proximal_rate(double trial_stress, double penalty) const = 0;

  /// The viscosity without its yield term τ_y/γ̇, regularised at the rate
  /// scale ε > 0 so that it stays finite and positive at rest, and its
  /// derivative in γ̇, for γ̇ ≥ 0.
  virtual Viscosity regularised_flow_viscosity(double rate, double rate_scale) const = 0;
};

}  // namespace softglass::macro
