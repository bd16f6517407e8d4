// Oscillatory shear, γ(t) = γ0 sin ωt at reduced frequency ω̃ = ω η_s/E*: the
// test a rheometer runs most on a soft glass (amplitude and frequency sweeps).
//
// The dynamics are those of steady shear — the same equation of motion,
// contact law, EHD drag and integrators — under a time-dependent drive
// (model/shear_drive.h): time runs in units of 1/γ̇_peak, γ̇_peak = γ0 ω, so
// the model's γ̃ is the peak rate γ0 ω̃ and a cycle lasts 2π γ0. The stress is
// sampled at `samples_per_cycle` equally spaced phases (a multiple of 4, so
// that the reversals of the strain, where the rate changes sign, are sample
// times: no step straddles one, which the neighbour list's strain bound and
// the drag's √u∥ near u∥ = 0 both rely on). After each cycle from
// `min_cycles` on the cycles are analysed (analysis/oscillation.h) and the run
// stops when they are periodic and G′, G″ are known to the target, or,
// unconverged, after `max_cycles`.
#pragma once

#include <functional>
#include <vector>

#include "micro/analysis/oscillation.h"
#include "micro/protocol/sampled_run.h"

namespace softglass::micro {

struct OscillationProtocol {
  double amplitude = 0.01;  // γ0
  double frequency = 1e-7;  // ω̃ = ω η_s / E*
  unsigned samples_per_cycle = 64;
  unsigned min_cycles = 4;  // the start-up cycle included
  unsigned max_cycles = 40;
  unsigned min_periodic_cycles = 3;
  double target_relative_error = 0.01;  // SE of G′ and G″ relative to |G*|

  void validate() const;
  /// γ̃ of the model: the peak rate γ0 ω̃.
  double peak_gamma_tilde() const { return amplitude * frequency; }
  /// One cycle in the run's time unit 1/γ̇_peak.
  double period() const;
};

/// An oscillatory run: the sampled series (σ tensors at the sample phases, the
/// cell's strain γ(t_k)), the responses of its complete cycles and their
/// periodic summary.
struct OscillationResult : SampledRun {
  std::vector<std::vector<double>> cycles;  // [cycle][oscillation_observable_names()]
  PeriodicSummary summary;
};

/// The responses of the complete cycles of `series` (a run of `protocol`
/// started at phase 0; sample k at phase 2πk/N).
std::vector<std::vector<double>> cycle_responses(const TimeSeries& series,
                                                 const OscillationProtocol& protocol);

/// The integrator of an oscillatory run: `spec` resolved for the peak rate
/// (and `stokes`: IntegratorSpec::resolved_for), its position tolerance (units of R) and the
/// implicit step's force residual (relative to the mean contact force) scaled by min(1, γ0), so
/// that the displacements and force changes of a small-amplitude cycle, ∝ γ0, are resolved as
/// finely as those of a unit strain.
IntegratorSpec oscillation_integrator(const IntegratorSpec& spec,
                                      const OscillationProtocol& protocol, StokesReference stokes);

/// Runs `flow`, driven by ShearDrive::oscillatory(γ0) at γ̃ = γ0 ω̃ from time 0
/// (std::invalid_argument otherwise), until periodic. `progress` gets the
/// time run so far (checkpoints as in sampled_run.h).
OscillationResult run_oscillation(OverdampedShear& flow, Integrator& integrator,
                                  const OscillationProtocol& protocol,
                                  const std::function<void(const ShearProgress&)>& progress = {},
                                  const ShearCheckpointing& checkpointing = {});

}  // namespace softglass::micro
