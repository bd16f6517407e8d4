// The augmented-Lagrangian method ALG2 (Fortin & Glowinski 1983) for the
// reduced scalar problem (scalar_problem.h) with the unregularised
// Herschel–Bulkley law: the scalar solver's alternative to regularisation
// (`method = augmented-lagrangian`).
//
// The functional J(u) = ∫ [Ψ(γ̇) − f u] ρ dx is not differentiable where
// γ̇ = s|∇u| = 0, which is where the material is rigid. Split the shear rate
// off as a field of its own, γ ≈ s∇u at the quadrature points, and enforce
// γ = s∇u with a multiplier λ (the stress) and a penalty r: the saddle point of
//
//     L_r(u, γ, λ) = ∫ [Ψ(|γ|) − f u + λ·(s∇u − γ) + (r/2)|s∇u − γ|²] ρ dx
//
// is the solution. ALG2 alternates, with the previous γ and λ:
//   1. u: r ∫ ρ s² ∇u·∇v = ∫ ρ f v − ∫ ρ s (λ − r γ)·∇v, a Laplace problem
//      whose matrix never changes (factorised once per mesh);
//   2. γ: pointwise, with the trial stress χ = λ + r s∇u: γ = 0 where
//      |χ| ≤ τ_y (rigid), else γ = g χ/|χ| with τ_y + K gⁿ + r g = |χ|
//      (ShearLaw::proximal_rate; Herschel–Bulkley's closed form or root);
//   3. λ ← λ + r (s∇u − γ).
// The rigid set {γ = 0} is then exactly the set where the stress is below the
// yield stress: no regularisation. The price is slow convergence (the
// constraint residual ‖s∇u − γ‖ falls roughly like 1/iterations), which is
// what the tolerance measures, relative to ‖γ‖ (or to the scene's rate scale
// where the material barely flows).
//
// Error estimate. The outputs converge like 1/k in the iteration k (Rheolef's
// experience, docs/macro.md), so after K iterations the error is about their
// change since iteration k times k/(K − k); solve() lets its caller record the
// outputs about a tenth of the iterations back for that.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <optional>
#include <vector>

#include "macro/fe/distributed_system.h"
#include "macro/fe/scalar_problem.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/regularised_law.h"

namespace softglass::macro::fe {

/// The discretisation of a section that ALG2 iterates on: the scalar solver's.
template <int dim>
struct SectionDiscretisation {
  const dealii::Mapping<dim>& mapping;
  const dealii::FiniteElement<dim>& fe;
  const dealii::DoFHandler<dim>& dof_handler;
  const SectionWeights& weights;
  MPI_Comm communicator;
};

template <int dim>
class AugmentedLagrangian {
 public:
  /// The penalty r is settings.al_relative_penalty times the scene's
  /// viscosity scale η(γ̇_c). `law` must outlive the method.
  AugmentedLagrangian(const SectionDiscretisation<dim>& section, DistributedSystem& system,
                      const dealii::AffineConstraints<double>& constraints, const ShearLaw& law,
                      const SolverSettings& settings);

  /// Iterates on the current mesh from u until the relative constraint
  /// residual reaches settings.al_tolerance; returns the iterations,
  /// NumericalError if al_max_iterations do not suffice. γ starts at s∇u and
  /// λ at the stress of `start_law` (the regularised law u solves; null: 0).
  /// `record` (if set) is called about every tenth of the iterations so far,
  /// after the local steps, for the error estimate.
  unsigned solve(VectorType& u, const Drive& drive, const RegularisedLaw* start_law,
                 const std::function<void()>& record = {});

  /// |γ| at quadrature point k of this rank's cells (QGauss(degree + 1), cell
  /// by cell) after the last iteration: exactly zero where rigid.
  double rate(std::size_t k) const { return rate_norm_[k]; }

  /// k/(K − k)'s inverse, (K − k)/k: the factor that turns the outputs' change
  /// since the last recorded iteration k into the error after K iterations.
  double error_divisor() const;

 private:
  void assemble_u_step(const Drive& drive, bool with_matrix, VectorType& rhs);
  /// Steps 2 and 3 at every quadrature point; returns ‖s∇u − γ‖ relative to
  /// ‖γ‖ (or to the rate scale of `drive` where the material barely flows).
  double local_steps(const VectorType& u, const Drive& drive);

  SectionDiscretisation<dim> section_;
  DistributedSystem& system_;
  const dealii::AffineConstraints<double>& constraints_;
  const ShearLaw& law_;
  SolverSettings settings_;
  double penalty_ = 0.0;
  std::optional<dealii::FEValues<dim>> fe_values_;  // of the current solve's mesh

  // Per quadrature point of this rank's cells: γ, λ and |γ|.
  std::vector<dealii::Tensor<1, dim>> rate_, multiplier_;
  std::vector<double> rate_norm_;
  // The last solve's iterations and the iteration its caller last recorded.
  unsigned iterations_ = 0, recorded_iteration_ = 0;
};

}  // namespace softglass::macro::fe
