// `micro oscillate`: amplitude and frequency sweeps of oscillatory shear.
#pragma once

#include "micro/app/sweep_work.h"

namespace softglass::micro {

/// Runs what is missing of the oscillation sweep, then writes its tables
/// (run_sweep, sweep_work.h).
void oscillate_command(const SweepOptions& options, const Workers& workers);

}  // namespace softglass::micro
