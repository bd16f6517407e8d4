// Athermal quasi-static shear (AQS): the γ̃ → 0 limit of the sheared dynamics.
//
// Small strain steps Δγ, each an affine shear of the whole configuration
// followed by a minimisation of the elastic energy at the new strain (Maloney &
// Lemaître's protocol). Between plastic events the configuration follows a
// local energy minimum; at an event the minimum disappears and the minimiser
// finds the next one. The EHD drag and the friction vanish from the stress as
// γ̃ → 0 (σ^v ∝ γ̃^{2/3}), so the stationary mean of σ^e is the dynamic yield
// stress σ_y(φ): the low end of every flow curve (docs/bridge.md).
//
// The minimiser is incremental_minimiser.h with Φ = E (Newton–CG, damped when
// indefinite, Armijo line search): the energy falls monotonically
// within every step. The guess for each step's non-affine displacement is the
// previous step's (linear response between events). Measured at Δγ = 1e-3
// (N = 1000, 5 strain, φ = 0.90 … 0.70): 9–22 Newton iterations per step,
// 30–33 CG iterations each (docs/sweeps.md, "Strain step").
//
// Usage: `aqs_flow_curve_point(packing system, settings)`; the result carries the
// sampled series and the same steady-state summary (MSER + blocking) as a
// sheared run (protocol/shear_run.h), with σ^v = 0. `micro sweep` runs it through
// protocol/quasi_static_run.h as the γ̃ = 0 case of every packing (docs/sweeps.md).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "micro/dynamics/incremental_counters.h"
#include "micro/model/contact_system.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

/// Δγ by default and at most. Over the `paper` sweep's quasi-static cases
/// (five φ, five packings each and five more at φ = 0.80) 1e-3 gives the σ_y,
/// N1, N2 and structure of the former 2e-4 within their errors (σ_y −0.09 ±
/// 0.33 % pooled) at a lower cost (bench/results/aqs_strain_step-2026-11-29.md).
inline constexpr double kDefaultAqsStrainStep = 1e-3;
inline constexpr double kMaxAqsStrainStep = 0.01;
/// The minimiser's tolerance (largest residual / mean contact force) by
/// default and at most. 1e-6 leaves the stress of a trajectory within 1.5e-6
/// of the mean stress of a 1e-9 one until a plastic event falls into another
/// minimum; over the paper sweep's ten quasi-static cases σ_y moves by
/// −0.03 ± 0.72 %, with fewer CG iterations
/// (bench/results/aqs_force_tolerance-2026-11-27.md).
inline constexpr double kDefaultAqsForceTolerance = 1e-6;
inline constexpr double kMaxAqsForceTolerance = 1e-3;

struct AqsSettings {
  double strain_step = kDefaultAqsStrainStep;         // Δγ
  double strain = 2.0;                                // total strain sheared
  double min_stationary_strain = 0.5;                 // for the steady-state analysis
  double relative_force = kDefaultAqsForceTolerance;  // max residual / mean contact force
  int max_iterations = 2000;                          // Newton iterations per strain step

  void validate() const;
};

struct AqsResult {
  TimeSeries series;           // one sample per strain step (viscous = 0)
  ShearSummary summary;        // stationary means: summary["sigma"] is σ_y
  std::vector<double> energy;  // elastic energy after each step (units E* R³)
  std::size_t steps = 0;
  IncrementalCounters minimiser;  // the minimisations' work (incremental_counters.h)
  std::size_t stress_drops = 0;   // steps where σ fell (plastic events)
  std::size_t unconverged_steps = 0;
  double seconds = 0.0;
};

/// Diagnostics of one AQS step, for tests: the energy after each Newton
/// iteration (relative to the start of the minimisation).
using AqsObserver = std::function<void(const std::vector<double>& energies)>;

/// Shears `system` quasi-statically from its current strain (it is moved).
AqsResult run_aqs(ContactSystem& system, const AqsSettings& settings,
                  const AqsObserver& observer = {});

/// The quasi-static flow-curve point of a packing: run_aqs on a copy.
AqsResult aqs_flow_curve_point(ContactSystem system, const AqsSettings& settings);

}  // namespace softglass::micro
