// Steady shear at fixed γ̃ (the paper's protocol, docs/physics.md): overdamped
// dynamics sampled every `sample_interval` of strain until the stresses are
// stationary and known to the requested accuracy (shear_protocol.h).
//
// The run is a class with one member per step — take a step, record a sample,
// decide whether to stop, save a checkpoint or restart from one — sharing the
// schedule (next sample, check, snapshot) and the counters.
#pragma once

#include <functional>
#include <memory>

#include "micro/dynamics/integrator.h"
#include "micro/model/overdamped_shear.h"
#include "micro/protocol/shear_protocol.h"

namespace softglass::micro {

/// Everything a run needs to go on from where it was: the particles in the
/// engine's order with the velocities that warm-start the next drag solve, the
/// strain, and the run's history and bookkeeping.
struct ShearCheckpoint {
  Particles particles;
  LeesEdwardsBox box;
  double start = 0.0;  // strain at which the run began
  double next_sample = 0.0, next_check = 0.0, next_snapshot = 0.0;
  double worst = 0.0;  // worst relative error at the last check
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

ShearResult run_shear(OverdampedShear& flow, Integrator& integrator, const ShearProtocol& protocol,
                      const std::function<void(const ShearProgress&)>& progress = {},
                      const ShearCheckpointing& checkpointing = {});

}  // namespace softglass::micro
