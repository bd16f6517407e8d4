// `micro sweep`: a flow curve over volume fractions, shear rates and packings.
#pragma once

#include "micro/app/sweep_work.h"

namespace softglass::micro {

/// Runs what is missing of the sweep, then writes the flow-curve tables
/// (run_sweep, sweep_work.h).
void sweep_command(const SweepOptions& options, const Workers& workers);

}  // namespace softglass::micro
