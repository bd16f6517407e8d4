// The driver every protocol of the overdamped dynamics shares — steady shear
// (shear_run.h) and oscillatory shear (oscillatory_run.h): take steps, sample
// the stress on a fixed schedule, ask the protocol's stopping rule, save
// checkpoints and restart from them.
//
// The run's clock is the flow's time (overdamped_shear.h): the strain itself
// in steady shear, time in units of 1/γ̇_ref under a drive. Samples land on
// their times (the integrator's step is cut there); the times are accumulated,
// start + interval + interval + …, whose rounding stays far below the slack of
// a sample (1e-9 of its interval) for the runs the protocols allow.
//
// The run is a class with one member per step — take a step, record a sample,
// decide whether to stop, save a checkpoint or restart from one — sharing the
// schedule (next sample, check, snapshot) and the counters.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "micro/dynamics/integrator.h"
#include "micro/model/overdamped_shear.h"
#include "micro/protocol/shear_protocol.h"

namespace softglass::micro {

/// When a run samples, checks its stopping rule and stores configurations,
/// and how long it may go on; in units of its clock.
struct SampleSchedule {
  double sample_interval;
  double check_interval;
  double first_check;        // clock since the start of the first check
  double max_length;         // clock since the start at which the run stops anyway
  double snapshot_interval;  // 0: no snapshots
};

/// What a protocol concludes after a sample. `check_due`: a scheduled check;
/// `at_end`: the run has reached its maximum length. Returns whether the run
/// stops, having set `run.converged` and `run.stop_reason` if so, and keeps
/// `worst`, the worst relative error at the last check (∞ before the first),
/// for the progress report and the checkpoints.
class StopRule {
 public:
  virtual ~StopRule() = default;
  virtual bool stops(const TimeSeries& series, bool check_due, bool at_end, SampledRun& run) = 0;
  double worst = std::numeric_limits<double>::infinity();
};

/// Everything a run needs to go on from where it was: the particles in the
/// engine's order with the velocities that warm-start the next drag solve, the
/// cell and the time, and the run's history and bookkeeping.
struct ShearCheckpoint {
  Particles particles;
  LeesEdwardsBox box;
  double start = 0.0;  // clock at which the run began
  double next_sample = 0.0, next_check = 0.0, next_snapshot = 0.0;
  double worst = 0.0;  // worst relative error at the last check
  /// The drive it was written under: its amplitude (0: steady shear) and the
  /// flow's time (steady shear: the cell's strain); absent from checkpoints
  /// written before oscillatory shear existed, which are steady.
  double amplitude = 0.0;
  std::optional<double> time;
  TimeSeries series;
  std::vector<Snapshot> snapshots;
  ShearCounters counters;  // up to the checkpoint
  double seconds = 0.0;    // wall time up to the checkpoint
};

/// Checkpoints every `every_steps` accepted steps. At each one the run starts
/// afresh from the checkpoint — new contact system, new integrator, velocities
/// and history restored — whether or not it was interrupted there, so a run
/// resumed from a checkpoint takes exactly the steps of an uninterrupted one
/// and ends with the same numbers, bit for bit.
struct ShearCheckpointing {
  std::size_t every_steps = 0;  // 0: never
  std::function<void(const ShearCheckpoint&)> save;
  std::function<std::unique_ptr<Integrator>()> new_integrator;
  const ShearCheckpoint* resume_from = nullptr;  // go on from here instead of starting
};

/// Runs `flow` on `schedule` until `rule` stops it; fills `run` (series,
/// snapshots, counters, conclusion, wall time). `progress` gets the clock
/// since the start, the maximum length and the rule's worst error after every
/// sample that does not stop the run.
void run_sampled(OverdampedShear& flow, Integrator& integrator, const SampleSchedule& schedule,
                 StopRule& rule, const std::function<void(const ShearProgress&)>& progress,
                 const ShearCheckpointing& checkpointing, SampledRun& run);

}  // namespace softglass::micro
