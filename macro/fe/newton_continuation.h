// Newton's method with a line search and continuation in the regularisation
// scale ε: the one nonlinear-solve policy of the finite-element solvers (the
// scalar solver and the Stokes solver), so that both take the same decisions.
//
// Newton. At the current iterate u the problem assembles its residual R(u) and
// Jacobian R'(u) for a regularised law (regularised_law.h); the update δ solves
// R'(u) δ = −R(u) (homogeneous on Dirichlet boundaries), and u ← u + αδ with α
// from the line search. Newton stops when the step is below the settings'
// newton tolerance times max |u|.
//
// Line search: two strategies, because the two problems differ in kind.
//   energy_slope      The scalar problems minimise a convex functional J
//                     (scalar_problem.h), and δ is a descent direction of it.
//                     If the full step does not reduce ‖R‖, α minimises J along
//                     δ: φ(α) = J(u + αδ) is convex, so its derivative
//                     φ'(α) = R(u + αδ)(δ) increases and its zero is found by
//                     regula falsi (to a tenth of φ'(0), at most 12 steps).
//                     Newton then converges from any start.
//   residual_halving  The Stokes problem is a saddle point in (u, p): there is
//                     no energy to descend, and φ' need not change sign. α
//                     halves (at most 12 times) until ‖R‖ decreases.
// Either strategy on the other problem would change the solvers' iterates and
// so the last digits of their results; docs/macro.md ("Nonlinear solver").
//
// Modified tangent. After a step the line search cut below 1/2, the next
// Jacobian raises the tangent viscosity τ' = dτ/dγ̇ to at least kTangentFloor
// times the secant viscosity η (the problem's assembler applies the floor it is
// given). Where the material has just yielded, τ' is orders of magnitude below η
// (n < 1, small ε), so the Newton step along the flow direction is huge and its
// region of validity tiny; the floor keeps the matrix positive definite in the
// velocity (the step stays a descent direction) and the step moderate. Once
// needed, the floor stays for the rest of the solve: dropping it after a whole
// step (as first done) let the next full-Newton step overshoot by 10⁴ |u| again,
// and at Bingham numbers of 10³ and more the solve alternated between the two
// until it ran out of iterations (bench/solver_envelope.sh). The floor changes
// the Jacobian only, not the residual: the converged solution is the same, the
// convergence linear instead of quadratic. It is the fallback of a failed
// solve: where pure Newton converges it is faster.
//
// Continuation. The smaller ε, the more η_ε varies (from τ_y/ε in a plug to
// K γ̇ⁿ⁻¹ in the flow) and the narrower the region where Newton converges
// quadratically. Continuation starts at a large ε and divides it by
// kContinuationFactor per stage down to the target, each stage starting from the
// previous one's solution. A stage that fails (plain, then modified Newton) is
// retried from the last converged stage with the step in ε square-rooted, while
// the step exceeds kSmallestContinuationStep (10 → 3.2 → 1.8 → 1.3).
//
// Every decision is taken on global quantities (norms and inner products of
// distributed vectors), so all ranks of a distributed mesh take the same path.
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <memory>
#include <string>

#include "macro/fe/distributed_system.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/regularised_law.h"

namespace softglass::macro::fe {

enum class LineSearch { energy_slope, residual_halving };

/// Assembles into the system's residual R(u) (and, with_matrix, its Jacobian)
/// for `law`, with τ' floored at tangent_floor·η in the Jacobian (0: none),
/// condensed with the homogeneous constraints.
using NewtonAssembler = std::function<void(const RegularisedLaw& law, const VectorType& u,
                                           bool with_matrix, double tangent_floor)>;

class NewtonContinuation {
 public:
  /// `problem` names the problem in messages ("Newton", "Stokes Newton").
  /// `law` (which must outlive the policy) is regularised with
  /// settings.regularisation at each ε.
  NewtonContinuation(std::string problem, LineSearch line_search, DistributedSystem& system,
                     const dealii::AffineConstraints<double>& homogeneous_constraints,
                     NewtonAssembler assemble, const ShearLaw& law, const SolverSettings& settings);

  /// Newton from u at one law; NumericalError if it does not converge. With
  /// allow_damping, a step shorter than 1/2 is followed by the modified tangent.
  unsigned solve(const RegularisedLaw& law, VectorType& u, bool allow_damping = false) const;

  /// Plain Newton from u; if that fails, modified Newton from the same u (the
  /// failed attempt counts as the maximum number of iterations).
  unsigned solve_damped_on_failure(const RegularisedLaw& law, VectorType& u) const;

  /// Continuation from ε = start down to ε = target (one stage if equal);
  /// returns the iterations and leaves the law at the last ε tried in `law`.
  unsigned continuation(double target, double start, VectorType& u,
                        std::unique_ptr<RegularisedLaw>& law) const;

 private:
  /// One solve from `start` into u; false (u back at `start`, the maximum
  /// number of iterations counted, the message kept) if it does not converge.
  bool attempt(const RegularisedLaw& law, const VectorType& start, bool allow_damping,
               VectorType& u, unsigned& iterations, std::string& failure) const;
  double step_length(const RegularisedLaw& law, const VectorType& u, const VectorType& update,
                     double residual_norm, VectorType& trial) const;
  double energy_slope_search(const RegularisedLaw& law, const VectorType& u,
                             const VectorType& update, double residual_norm,
                             VectorType& trial) const;
  double residual_halving_search(const RegularisedLaw& law, const VectorType& u,
                                 const VectorType& update, double residual_norm,
                                 VectorType& trial) const;

  std::string problem_;
  LineSearch line_search_;
  DistributedSystem& system_;
  const dealii::AffineConstraints<double>& homogeneous_constraints_;
  NewtonAssembler assemble_;
  const ShearLaw& law_;
  std::string regularisation_;
  double tolerance_;
  unsigned max_iterations_;
};

}  // namespace softglass::macro::fe
