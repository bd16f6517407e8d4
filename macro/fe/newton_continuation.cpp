#include "macro/fe/newton_continuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/errors.h"

namespace softglass::macro::fe {

namespace {

// A failed continuation stage is retried with the step ε_prev/ε square-rooted
// while it exceeds this (10 → 3.2 → 1.8 → 1.3: three retries).
constexpr double kSmallestContinuationStep = 1.2;
// energy_slope: stop when |φ'| has dropped to this fraction of φ'(0) (an
// inexact but sufficient line search), or after this many steps.
constexpr double kSlopeReduction = 0.1;
constexpr int kSlopeSteps = 12;
// residual_halving: at most this many halvings of the step.
constexpr int kHalvings = 12;
// A step shorter than this is followed by the modified tangent.
constexpr double kFullStep = 0.5;

}  // namespace

NewtonContinuation::NewtonContinuation(
    std::string problem, LineSearch line_search, DistributedSystem& system,
    const dealii::AffineConstraints<double>& homogeneous_constraints, NewtonAssembler assemble,
    const ShearLaw& law, const SolverSettings& settings)
    : problem_(std::move(problem)),
      line_search_(line_search),
      system_(system),
      homogeneous_constraints_(homogeneous_constraints),
      assemble_(std::move(assemble)),
      law_(law),
      regularisation_(settings.regularisation),
      tolerance_(settings.newton_tolerance),
      max_iterations_(settings.max_newton_iterations) {}

unsigned NewtonContinuation::solve(const RegularisedLaw& law, VectorType& u,
                                   bool allow_damping) const {
  VectorType update = system_.vector(), trial = system_.vector();
  bool damped = false;
  for (unsigned iteration = 1; iteration <= max_iterations_; ++iteration) {
    assemble_(law, u, true, damped ? kTangentFloor : 0.0);
    const double residual_norm = system_.residual.l2_norm();
    system_.factorise();
    system_.solve(update, system_.residual);
    update *= -1.0;
    homogeneous_constraints_.distribute(update);
    const double alpha = step_length(law, u, update, residual_norm, trial);
    u.add(alpha, update);
    damped = allow_damping && (damped || alpha < kFullStep);
    // SOFTGLASS_MACRO_DEBUG=1 traces every Newton step (convergence problems).
    if (std::getenv("SOFTGLASS_MACRO_DEBUG"))
      fmt::print(stderr, "{} eps={:.3g} it={} |R|={:.3e} alpha={:.3g} |du|={:.3e}\n", problem_,
                 law.rate_scale(), iteration, residual_norm, alpha, update.linfty_norm());
    const double scale = std::max(u.linfty_norm(), std::numeric_limits<double>::min());
    if (alpha * update.linfty_norm() <= tolerance_ * scale) return iteration;
  }
  throw NumericalError(fmt::format(
      "{} did not converge in {} iterations ({} regularisation, eps = {:.3g} 1/s, {} dofs)",
      problem_, max_iterations_, law.name(), law.rate_scale(), system_.owned.size()));
}

double NewtonContinuation::step_length(const RegularisedLaw& law, const VectorType& u,
                                       const VectorType& update, double residual_norm,
                                       VectorType& trial) const {
  return line_search_ == LineSearch::energy_slope
             ? energy_slope_search(law, u, update, residual_norm, trial)
             : residual_halving_search(law, u, update, residual_norm, trial);
}

// The full step if it does not raise ‖R‖; else regula falsi on
// φ'(α) = R(u + αδ)(δ), which increases from φ'(0) < 0 (δ a descent direction).
// system_.residual holds R(u) on entry.
double NewtonContinuation::energy_slope_search(const RegularisedLaw& law, const VectorType& u,
                                               const VectorType& update, double residual_norm,
                                               VectorType& trial) const {
  const double slope0 = system_.residual * update;
  const auto slope_at = [&](double alpha) {
    trial = u;
    trial.add(alpha, update);
    assemble_(law, trial, false, 0.0);
    return system_.residual * update;
  };
  double alpha = 1.0;
  const double d_full = slope_at(1.0);
  if (system_.residual.l2_norm() > residual_norm && slope0 < 0.0 && d_full > 0.0) {
    double lo = 0.0, hi = 1.0, d_lo = slope0, d_hi = d_full;
    for (int k = 0; k < kSlopeSteps; ++k) {
      alpha = lo - d_lo * (hi - lo) / (d_hi - d_lo);
      const double d = slope_at(alpha);
      if (std::abs(d) <= kSlopeReduction * std::abs(slope0)) break;
      (d < 0.0 ? lo : hi) = alpha;
      (d < 0.0 ? d_lo : d_hi) = d;
    }
  }
  return alpha;
}

// α = 1, 1/2, 1/4, ... until ‖R(u + αδ)‖ < ‖R(u)‖ (the last one tried otherwise).
double NewtonContinuation::residual_halving_search(const RegularisedLaw& law, const VectorType& u,
                                                   const VectorType& update, double residual_norm,
                                                   VectorType& trial) const {
  double alpha = 1.0;
  for (int k = 0; k < kHalvings; ++k, alpha *= 0.5) {
    trial = u;
    trial.add(alpha, update);
    assemble_(law, trial, false, 0.0);
    if (system_.residual.l2_norm() < residual_norm) break;
  }
  return alpha;
}

bool NewtonContinuation::attempt(const RegularisedLaw& law, const VectorType& start,
                                 bool allow_damping, VectorType& u, unsigned& iterations,
                                 std::string& failure) const {
  u = start;
  try {
    iterations += solve(law, u, allow_damping);
    return true;
  } catch (const NumericalError& error) {
    iterations += max_iterations_;
    failure = error.what();
    u = start;
    return false;
  }
}

unsigned NewtonContinuation::solve_damped_on_failure(const RegularisedLaw& law,
                                                     VectorType& u) const {
  const VectorType start = u;
  unsigned iterations = 0;
  std::string failure;
  if (attempt(law, start, false, u, iterations, failure) ||
      attempt(law, start, true, u, iterations, failure))
    return iterations;
  throw NumericalError(failure);
}

unsigned NewtonContinuation::continuation(double target, double start, VectorType& u,
                                          std::unique_ptr<RegularisedLaw>& law) const {
  unsigned iterations = 0;
  double eps = std::max(start, target), converged_eps = 0.0;
  VectorType converged = u;
  std::string failure;
  while (true) {
    law = make_regularised_law(regularisation_, law_, eps);
    const VectorType stage_start = u;
    if (!attempt(*law, stage_start, false, u, iterations, failure) &&
        !attempt(*law, stage_start, true, u, iterations, failure)) {
      // Retry halfway (in log ε) from the last converged stage, while the
      // step is still worth shrinking.
      if (converged_eps == 0.0 || converged_eps / eps < kSmallestContinuationStep)
        throw NumericalError(failure);
      eps = std::sqrt(converged_eps * eps);
      u = converged;
      continue;
    }
    converged = u;
    converged_eps = eps;
    if (eps <= target * (1.0 + 1e-12)) return iterations;
    eps = std::max(eps / kContinuationFactor, target);
  }
}

}  // namespace softglass::macro::fe
