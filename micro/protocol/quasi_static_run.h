// Athermal quasi-static shear (AQS) as a run: the γ̃ → 0 case of a sweep, whose
// stationary mean σ is the dynamic yield stress σ_y (docs/bridge.md).
//
// dynamics/aqs.h shears a configuration by a fixed strain. A run needs what a
// sheared run has (shear_run.h): its stopping rule (min strain, stationary,
// σ, N1, N2 to the target error, or max strain), a series sampled at the
// protocol's sample interval, snapshots for the structure analysis, and
// checkpoints. So the run is a chain of run_aqs segments, each one snapshot
// interval long (else one check interval; at most one strain). Every segment
// starts afresh from where the last ended — a new contact system built from
// the configuration in label order, the first step guessed affine — whether or
// not the run was interrupted there, so a run resumed from a checkpoint ends
// with the numbers of an uninterrupted one, bit for bit.
//
// Each sample is the mean of σ^e and Z over its round(sample interval / Δγ)
// strain steps: the steady-state mean then uses every step, while the stored
// series stays as long as a sheared run's. σ^v = 0 and the layering S_y is
// not measured (0).
#pragma once

#include <functional>
#include <limits>
#include <memory>

#include "micro/protocol/aqs.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

/// The minimisation of each strain step (dynamics/aqs.h); the strain comes
/// from the protocol.
struct QuasiStaticSettings {
  double strain_step = AqsSettings{}.strain_step;        // Δγ
  double relative_force = AqsSettings{}.relative_force;  // minimiser tolerance
  int max_iterations = AqsSettings{}.max_iterations;     // Newton iterations per step
};

/// Where a quasi-static run is, enough to go on from there.
struct QuasiStaticCheckpoint {
  Particles particles;  // label order, in the cell
  LeesEdwardsBox box;
  double start = 0.0;       // strain at which the run began
  double next_check = 0.0;  // strain since the start of the next steady-state check
  double worst = std::numeric_limits<double>::infinity();  // at the last check
  double last_sigma = 0.0;  // σ after the last step, for counting stress drops
  TimeSeries series;
  std::vector<Snapshot> snapshots;
  ShearCounters counters;  // steps, Newton and CG iterations
  std::size_t stress_drops = 0, unconverged_steps = 0;
  double seconds = 0.0;  // wall time up to the checkpoint
};

/// The strain step a checkpoint's run took (the strain it sheared over its
/// steps), 0 before its first step.
double strain_step_of(const QuasiStaticCheckpoint& checkpoint);

/// Checkpoints every `every_steps` strain steps (at the end of a segment).
/// `{}` initialisers: a caller may name one field alone.
struct QuasiStaticCheckpointing {
  std::size_t every_steps{};  // 0: never
  std::function<void(const QuasiStaticCheckpoint&)> save{};
  const QuasiStaticCheckpoint* resume_from{};  // go on from here instead of starting
};

struct QuasiStaticResult {
  /// As a sheared run's: series, snapshots, summary (summary["sigma"] is σ_y),
  /// converged, stop reason, seconds; counters hold steps, Newton and CG
  /// iterations and the strain step.
  ShearResult run;
  std::size_t stress_drops = 0;       // steps where σ fell (plastic events)
  std::size_t unconverged_steps = 0;  // minimisations that missed their tolerance
  Particles final_particles;          // label order
  LeesEdwardsBox final_box;
};

/// Shears the configuration `particles` (label order) in `box` quasi-statically
/// until the stopping rule of `protocol`. `progress` is called after every
/// segment. Throws InputError when the strain step exceeds the sample interval.
QuasiStaticResult run_quasi_static(const Particles& particles, const LeesEdwardsBox& box,
                                   std::shared_ptr<const ContactLaw> law, double skin,
                                   const QuasiStaticSettings& settings,
                                   const ShearProtocol& protocol,
                                   const std::function<void(const ShearProgress&)>& progress = {},
                                   const QuasiStaticCheckpointing& checkpointing = {});

}  // namespace softglass::micro
