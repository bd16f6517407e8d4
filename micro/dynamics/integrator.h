// Time integrators for the overdamped shear dynamics: one small interface, one
// scheme per file, chosen by name (`scheme = euler` in the parameter file). A
// new scheme is its file — a class deriving from Integrator and a function
// returning its registry entry (IntegratorEntry <name>_integrator()) — plus one
// line in integrators/registered_integrators.h.
//
// Schemes (in integrators/): `euler` (explicit, adaptive_euler.cpp), and for
// the stiff low-γ̃ regime `implicit` (backward Euler as a minimising movement)
// and `bdf2` (its second-order sibling), both in backward_euler.cpp;
// docs/integrators.md compares them. The default, `auto`, picks one by the
// shear rate. The quasi-static limit
// γ̃ → 0 is not an integrator but a protocol of its own (aqs.h).
//
// An integrator advances an OverdampedShear by one accepted step at a time and
// keeps the flow evaluated at its current state between calls, so the caller
// can read the stress after every step.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "common/registry.h"
#include "micro/dynamics/incremental_counters.h"
#include "micro/model/overdamped_shear.h"
#include "micro/model/stokes_friction.h"

namespace softglass::micro {

/// Why a step was rejected (and retried).
enum class Rejection {
  error,   // the local error estimate exceeds the tolerance
  list,    // the solve left the neighbour list's reach (implicit schemes)
  solver,  // the nonlinear solve did not converge (implicit schemes)
};

struct IntegratorStats {
  std::size_t accepted = 0;
  std::size_t rejected = 0;
  // `rejected` by cause (Rejection); they add up to it.
  std::size_t rejected_error = 0, rejected_list = 0, rejected_solver = 0;
  double smallest_step = 0.0;
  double largest_step = 0.0;
  double last_step = 0.0;
  // Implicit schemes: the frozen drags computed (one contact pass each; a
  // retry keeps its step's; none without drag), and the work of the step
  // solves, one per step tried, accepted and rejected together
  // (incremental_counters.h).
  std::size_t drag_freezes = 0;
  IncrementalCounters minimiser;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;

  /// Takes one accepted step of at most `max_step` strain and returns its size.
  virtual double step(OverdampedShear& flow, double max_step) = 0;

  const IntegratorStats& stats() const { return stats_; }

 protected:
  void record_accepted(double dt);
  void record_rejected(Rejection cause);
  IntegratorStats stats_;
};

struct IntegratorSpec {
  // A scheme of the registry, or `auto`: the cheapest scheme that is accurate
  // at the run's rate (resolved_for).
  std::string name = "auto";
  double tolerance = 0.0;           // local position error per step, units of R; 0: the scheme's
  double stability_fraction = 0.8;  // fraction of the explicit stability limit 2/λ
  double max_step = 0.05;           // time: strain in steady shear (shear_drive.h)
  // `implicit`, `bdf2`: the nonlinear solve of a step is converged when the largest
  // residual force is below this × the mean contact force.
  double solver_tolerance = 1e-7;

  void validate() const;
  /// The concrete scheme and tolerance for a run at `gamma_tilde` whose Stokes
  /// friction acts against `stokes`. `auto` is `euler` at γ̃ ≥
  /// kAutoImplicitBelow with the friction against the affine flow, and `bdf2`
  /// otherwise; a tolerance of 0 becomes the scheme's default
  /// (IntegratorTraits). Why: docs/integrators.md measures both schemes' error
  /// and cost by rate. Below the split `euler` is out of reach (its step ∝ γ̃).
  /// With the friction between neighbours every explicit step solves for the
  /// velocities through the pair dashpots, a system as costly as an implicit
  /// step's, and `bdf2`, with far fewer steps, is the cheaper up to γ̃ = 1e-2.
  IntegratorSpec resolved_for(double gamma_tilde, StokesReference stokes) const;
};

inline constexpr double kAutoImplicitBelow = 1e-5;

/// What the tools know of a scheme besides its factory.
struct IntegratorTraits {
  /// The tolerance used when none is given (docs/integrators.md measures it).
  double default_tolerance = 1e-4;
  /// Estimated cost of a case (sweep planning): seconds of one core per 5
  /// strain at N = 1000 and γ̃ = 1e-5, growing like γ̃^rate_exponent (but not
  /// below floor_seconds) and like
  /// N (explicit schemes) or N^1.35 (schemes that minimise: `minimises`).
  double seconds_at_reference = 25.0;
  double rate_exponent = -0.8;
  /// The least a case costs, whatever the rate (seconds per 5 strain at N = 1000).
  double floor_seconds = 0.0;
  bool minimises = false;
};

using IntegratorEntry = ComponentEntry<Integrator, IntegratorSpec, IntegratorTraits>;

/// Every scheme (integrators/registered_integrators.h).
const Registry<IntegratorEntry>& integrators();

/// The tolerance a scheme uses when none is given (its traits).
double default_tolerance(const std::string& scheme);

/// `spec` must name a scheme of the registry (resolve `auto` first).
std::unique_ptr<Integrator> make_integrator(const IntegratorSpec& spec);

}  // namespace softglass::micro
