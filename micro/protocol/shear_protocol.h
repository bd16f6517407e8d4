// What every shear protocol shares — steady shear at fixed γ̃ (shear_run.h) and
// quasi-static shear (quasi_static_run.h): the run length and stopping rule,
// the sampled series and its steady-state summary, the record of a run.
//
// A run goes on until the stresses are stationary and known to the requested
// accuracy (docs/physics.md, "Protocol").
//
// The stress tensors are sampled every `sample_interval` of strain. Every
// `check_interval` the series is analysed (analysis/steady_state.h): the start-up
// transient is removed by MSER-5 applied to σ, N1 and N2 together, and the means
// of the rest get standard errors by automated blocking. The run stops when
//   • at least `min_strain` has been sheared,
//   • the transient is resolved and the stationary part spans `min_stationary_strain`,
//   • every error bar is reliable and |SE/mean| ≤ `target_relative_error` for σ, N1, N2,
//   • and the stationary part does not drift (drift_statistic, |z| ≤ 3),
// or, unconverged, at `max_strain`, or when the sample has layered: the layering
// order parameter S_y (analysis/layering.h) is sampled with the stress, and a
// run stops when its mean over the last 2 strain exceeds kLayeredThreshold
// (at δ = 10 %, γ̃ = 1e-4 this happens after 20–30 strain, whatever N).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "micro/analysis/steady_state.h"
#include "micro/dynamics/incremental_counters.h"
#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

struct ShearProtocol {
  double sample_interval = 0.01;
  double snapshot_interval = 0.1;  // strain between stored configurations (0: none)
  double check_interval = 1.0;
  double min_strain = 5.0;
  double max_strain = 200.0;
  double min_stationary_strain = 5.0;
  double target_relative_error = 0.05;

  void validate() const;
};

/// The sampled history of a run.
struct TimeSeries {
  std::vector<double> strain;
  std::vector<Eigen::Matrix3d> elastic, viscous;  // σ^e, σ^v (units of E*)
  std::vector<Eigen::Matrix3d> film;              // σ^film ⊆ σ^v, the EHD films' part
  std::vector<double> coordination;               // Z = 2 × contacts / N
  std::vector<double> layering;                   // S_y, analysis/layering.h
  std::vector<double> step;                       // last accepted step (strain)

  std::size_t size() const { return strain.size(); }
  /// One scalar observable over the whole series, e.g. σ_yx^e.
  std::vector<double> component(const std::string& observable) const;
};

/// Names of the scalar observables: σ, N1, N2, Π and their elastic and viscous
/// parts and the films' share of the viscous one ("sigma", "sigma_elastic",
/// "sigma_viscous", "sigma_film", "N1", …).
const std::vector<std::string>& shear_observable_names();

struct ShearSummary {
  double transient_strain = 0.0;  // removed as start-up
  double averaged_strain = 0.0;   // stationary window
  bool transient_resolved = false;
  std::vector<ObservableEstimate> observables;  // in shear_observable_names() order
  double elastic_to_viscous = 0.0;              // σ^e / σ^v
  double elastic_to_film = 0.0;                 // σ^e / σ^film, the paper's ratio
  double coordination = 0.0;                    // mean Z over the stationary part
  double drift = 0.0;                           // largest |z| of σ, N1, N2 (drift_statistic)
  double layering = 0.0;                        // mean S_y over the stationary part
  bool layered() const;

  const MeanEstimate& operator[](const std::string& name) const;
  /// Largest |SE/mean| among σ, N1, N2.
  double worst_relative_error() const;
};

/// Steady-state analysis of a series (usable at run time and afterwards).
ShearSummary summarise(const TimeSeries& series, double min_stationary_strain);

/// The stopping rule above, on a summary: stationary (transient resolved, no
/// drift) with reliable errors of σ, N1 and N2 within the target. Shared by the
/// sheared and the quasi-static runs (quasi_static_run.h).
bool meets_stopping_rule(const ShearSummary& summary, const ShearProtocol& protocol);
/// The stop reasons a run records: met its rule, or reached `max_strain` first.
std::string converged_stop_reason(const ShearSummary& summary);
std::string max_strain_stop_reason(const ShearSummary& summary, const ShearProtocol& protocol);

/// What a run cost, in counts (docs/output.md, `/shear/counters`).
struct ShearCounters {
  ShearCounters& operator+=(const ShearCounters& more);
  std::size_t steps = 0, rejected_steps = 0, evaluations = 0, neighbour_builds = 0;
  // The velocity solves of the evaluations (AQS: the minimisations).
  std::size_t fixed_point_sweeps = 0, newton_iterations = 0, cg_iterations = 0;
  double smallest_step = 0.0, largest_step = 0.0;
  // rejected_steps by cause (integrator.h, Rejection).
  std::size_t rejected_error = 0, rejected_list = 0, rejected_solver = 0;
  // The implicit steps' frozen drags (integrator.h), and the minimisations of
  // the implicit steps or of AQS.
  std::size_t drag_freezes = 0;
  IncrementalCounters minimiser;
  bool operator==(const ShearCounters&) const = default;
};

/// A configuration of the run, for structure analysis afterwards.
struct Snapshot {
  double strain;
  std::vector<Vec3> position;  // label order, in the cell
};

/// What every sampled run yields: its history, how it ended and its cost.
struct SampledRun {
  TimeSeries series;
  std::vector<Snapshot> snapshots;
  ShearCounters counters;
  bool converged = false;
  std::string stop_reason;
  double seconds = 0.0;
};

/// A steady-shear (or quasi-static) run: the sampled run and its steady-state summary.
struct ShearResult : SampledRun {
  ShearSummary summary;
};

struct ShearProgress {
  double strain;  // sheared so far (under a drive: time run so far)
  double max_strain;
  double worst_relative_error;  // at the last check (∞ before the first)
};

/// The cell as a checkpoint file holds it (side and one double of strain), so
/// that a run continued past a checkpoint and one resumed from it start their
/// next part from the very same cell.
LeesEdwardsBox checkpointed_cell(const LeesEdwardsBox& box);

/// The decision after a new sample, shared by the protocols: at a due check the
/// series is summarised, `worst` updated and the stopping rule applied — then
/// `own_reason`, a protocol's own reason to stop (e.g. a layered sample); at
/// the maximum strain the run stops unconverged. Fills `result`'s summary,
/// `converged` and `stop_reason`; returns whether the run stops.
bool stops_after_sample(const TimeSeries& series, const ShearProtocol& protocol, bool check_due,
                        bool at_max_strain, ShearResult& result, double& worst,
                        const std::function<std::optional<std::string>()>& own_reason = {});

}  // namespace softglass::micro
