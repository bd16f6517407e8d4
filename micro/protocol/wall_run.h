// Steady shear between two smooth walls (contact/wall_contacts.h): the walls
// move with the affine flow at their heights, imposing the apparent rate γ̃ of
// the model on the gap; the run samples the wall and bulk stresses, the slip
// and the velocity profile (analysis/wall_sample.h) every `sample_interval`
// of strain up to `strain`, and summarises the stationary part (MSER-5
// truncation and blocking errors, analysis/steady_state.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "micro/analysis/steady_state.h"
#include "micro/analysis/wall_sample.h"
#include "micro/dynamics/integrator.h"

namespace softglass::micro {

struct WallRunSpec {
  double strain = 10.0;
  double sample_interval = 0.02;
  WallSampleSettings sampling;

  void validate() const;
};

struct WallRunResult {
  std::vector<double> strain;
  std::vector<WallSample> samples;
  double seconds = 0.0;
  std::size_t steps = 0;
};

/// Shears `flow` (whose system has walls) with `integrator` from its strain on.
WallRunResult run_wall_shear(OverdampedShear& flow, Integrator& integrator, const WallRunSpec& spec,
                             const std::function<void(double)>& progress = {});

/// The observables of a wall run, each a series over the samples: wall_stress
/// (the two walls' mean σ_w), wall_stress_lower/upper, bulk_stress,
/// bulk_stress_elastic, balance (bulk_stress − reservoir_term: σ_w,lo by force
/// balance), bulk_rate, slip_velocity, normal_stress (the walls' mean),
/// wall_contacts (per area, the walls' mean), load_per_contact.
std::vector<std::string> wall_observable_names();
std::vector<double> wall_observable_series(const WallRunResult& run, const std::string& name);

struct WallRunSummary {
  std::size_t transient_samples = 0, stationary_samples = 0;
  bool converged = false;  // analysis/steady_state.h's verdict
  std::vector<ObservableEstimate> estimates;  // by wall_observable_names()
  std::vector<double> profile, profile_error;  // mean u_x per bin over the stationary part
};

/// Stationary part: the MSER-5 truncation of wall_stress, bulk_stress and
/// slip_velocity. std::invalid_argument with fewer than 20 samples.
WallRunSummary summarise_wall_run(const WallRunResult& run);

}  // namespace softglass::micro
