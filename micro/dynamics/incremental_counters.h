// The work of the incremental minimiser (incremental_minimiser.h), counted:
// what the implicit step (backward_euler.cpp) and the quasi-static shear
// (aqs.h) spend their time on, in units that do not depend on the machine. A
// header of its own so that the run's counters (shear_protocol.h) carry it
// without the minimiser. docs/integrators.md says what each count costs.
#pragma once

#include <cstddef>

namespace softglass::micro {

/// Counters over the lifetime of a minimiser; deterministic, like the solves.
struct IncrementalCounters {
  std::size_t solves = 0;             // calls of minimise: one per step tried (AQS: + restarts)
  std::size_t iterations = 0;         // outer Newton iterations
  std::size_t cg_iterations = 0;      // CG iterations of their linear solves
  std::size_t force_evaluations = 0;  // force-kernel passes (Φ and ∇Φ at a point)
  std::size_t assemblies = 0;         // Hessian models built
  std::size_t damping_raises = 0;     // Levenberg–Marquardt μ raised (negative curvature met)
  std::size_t backtracks = 0;         // line-search trials shortened (t halved)

  IncrementalCounters& operator+=(const IncrementalCounters& more) {
    solves += more.solves;
    iterations += more.iterations;
    cg_iterations += more.cg_iterations;
    force_evaluations += more.force_evaluations;
    assemblies += more.assemblies;
    damping_raises += more.damping_raises;
    backtracks += more.backtracks;
    return *this;
  }
  /// The counts since `before` (an earlier state of the same counters).
  IncrementalCounters operator-(const IncrementalCounters& before) const {
    return {solves - before.solves,
            iterations - before.iterations,
            cg_iterations - before.cg_iterations,
            force_evaluations - before.force_evaluations,
            assemblies - before.assemblies,
            damping_raises - before.damping_raises,
            backtracks - before.backtracks};
  }
  bool operator==(const IncrementalCounters&) const = default;
};

}  // namespace softglass::micro
