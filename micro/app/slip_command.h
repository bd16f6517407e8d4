// `micro slip FILE.prm`: particles sheared between two smooth walls
// (docs/physics.md, "Wall slip") at each apparent rate of subsection `walls`,
// for each packing: per run an HDF5 file (the observables' series, the
// stationary means with their errors, the velocity profile) and a CSV of the
// profile; slip.csv gathers the runs. A run whose files exist is skipped, so
// a rerun goes on where an interrupted one stopped.
#pragma once

#include "micro/app/commands.h"

namespace softglass::micro {

void slip_command(const CommandOptions& options);

}  // namespace softglass::micro
