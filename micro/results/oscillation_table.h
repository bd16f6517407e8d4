// The tables of `micro oscillate` (docs/oscillation.md): one row per
// (φ, ω̃, γ0) averaged over its packings, and one row per run; as CSV with
// units in every column name and as HDF5, like the flow-curve tables.
#pragma once

#include <vector>

#include "common/unit_table.h"
#include "micro/io/oscillation_group.h"
#include "micro/results/packing_average.h"

namespace softglass::micro {

struct OscillationAverage {
  std::size_t runs = 0, converged_runs = 0, particles = 0, periodic_cycles = 0;
  double volume_fraction = 0.0, amplitude = 0.0, frequency = 0.0;
  AveragedObservable shear_modulus;          // static G0 of the packings (six shears)
  AveragedObservable flow_gradient_modulus;  // their x–y static modulus
  std::vector<AveragedObservable> observables;            // oscillation_observable_names() order
};

/// Throws InputError unless the runs share φ, γ0, ω̃ and N and start from
/// different packings.
OscillationAverage average_oscillations(const std::vector<StoredOscillationSummary>& runs);

/// One row per state point, in the order given.
UnitTable oscillation_table(const std::vector<OscillationAverage>& points);

/// One row per run; `seeds[k]` is the packing seed of `runs[k]`.
UnitTable oscillation_packing_table(const std::vector<StoredOscillationSummary>& runs,
                                    const std::vector<unsigned>& seeds);

}  // namespace softglass::micro
