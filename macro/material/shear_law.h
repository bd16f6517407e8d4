// The constitutive law of the finite-element solvers and of the exact
// references: what they need to know of a material's shear behaviour, and
// nothing of its form.
//
// A generalised-Newtonian material with (possibly) a yield stress: rigid where
// the stress magnitude |τ| = √(½ τ:τ) is at most τ_y, elsewhere τ = 2η(γ̇)D with
// γ̇ = √(2D:D) (docs/macro.md, "Conventions"). Every law is written as
//
//     τ(γ̇) = τ_y + Δ(γ̇),   Δ(0) = 0,  Δ increasing,
//
// the yield stress plus the excess stress Δ of the flowing material. The users
// of the interface need
//   - the yield stress, to tell yielded from rigid material (outputs, the
//     cells a yield surface crosses);
//   - τ(γ̇), η(γ̇) and γ̇(τ): stresses, the viscosity scale of a scene, rate
//     scales; Δ(γ̇) and its inverse on their own, so that a thinly yielded
//     layer (Δ ≪ τ_y) keeps all its digits (exact/couette.h);
//   - the local flow index n(γ̇) = d ln Δ / d ln γ̇ (Herschel–Bulkley: n);
//   - the viscous part of η regularised at a rate scale ε, with its
//     derivative: the regularised laws (regularised_law.h) add it to their
//     regularised yield term, and Newton linearises the sum. It is defined
//     once for every law (below) from Δ and n;
//   - the proximal step of the augmented-Lagrangian method (ALG2).
// The laws: Herschel–Bulkley (herschel_bulkley.h; Bingham, power law and
// Newtonian are its special cases) and the tabulated law of a simulated flow
// curve (tabulated_law.h). A new law is a new file with a class implementing
// this interface and a material model that makes it (material_model.h).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

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

  /// One line stating the law and its parameters, for listings.
  virtual std::string description() const = 0;

  /// τ(γ̇) of the flowing material for γ̇ ≥ 0 (its limit τ_y at γ̇ = 0).
  virtual double stress(double rate) const = 0;

  /// Δ(γ̇) = τ(γ̇) − τ_y for γ̇ ≥ 0, computed as such (not as a difference).
  virtual double excess_stress(double rate) const = 0;

  /// γ̇ at τ = τ_y + excess, excess ≥ 0: the inverse of excess_stress.
  virtual double rate_at_excess(double excess) const = 0;

  /// n(γ̇) = d ln Δ / d ln γ̇ > 0 at γ̇ > 0.
  virtual double local_flow_index(double rate) const = 0;

  /// Δ(γ̇) and n(γ̇) together, γ̇ > 0: what the regularised viscosity needs at
  /// every quadrature point of every Newton step. A law that finds both in
  /// one evaluation (a table: one interval look-up) overrides it.
  virtual std::pair<double, double> excess_and_flow_index(double rate) const {
    return {excess_stress(rate), local_flow_index(rate)};
  }

  /// The excess stresses at which Δ is only finitely smooth (a table's
  /// nodes), empty for an analytic law: quadratures over the law split there.
  virtual std::vector<double> excess_breakpoints() const { return {}; }

  /// The rates [1/s] the law was given at (a table's first and last), where
  /// it is data rather than extrapolation; none for a closed-form law.
  virtual std::optional<std::pair<double, double>> rate_window() const { return std::nullopt; }

  /// The smallest and largest local flow index over all rates.
  virtual std::pair<double, double> flow_index_range() const = 0;

  /// The secant viscosity τ(γ̇)/γ̇ for γ̇ > 0.
  virtual double viscosity(double rate) const = 0;

  /// The inverse flow curve γ̇(τ) for τ ≥ 0: zero up to τ_y.
  virtual double rate(double stress) const = 0;

  /// ALG2's local step: the rate s ≥ 0 minimising φ(s) + ½ r s² − χ s, φ the
  /// dissipation potential, for a trial stress χ ≥ 0 and penalty r ≥ 0.
  virtual double proximal_rate(double trial_stress, double penalty) const = 0;

  /// The viscosity without its yield term, Δ(γ̇)/γ̇, regularised at the rate
  /// scale ε > 0 so that it stays finite and positive at rest, and its
  /// derivative in γ̇, for γ̇ ≥ 0: Δ(s)/s at s = √(γ̇² + ε²), whose derivative
  /// is (n(s) − 1) Δ(s) γ̇ / s³. For Herschel–Bulkley that is K (γ̇² + ε²)^{(n−1)/2},
  /// exactly K for n = 1: unbounded at rest no longer for n < 1, and no longer
  /// vanishing there for n > 1 (which would leave the problem singular).
  Viscosity regularised_flow_viscosity(double rate, double rate_scale) const;
};

}  // namespace softglass::macro
