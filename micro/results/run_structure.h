// Structure analysis of the stationary part of a run: every stored snapshot
// sampled (in parallel), then averaged with errors (structure.h).
#pragma once

#include <span>

#include "micro/analysis/structure.h"
#include "micro/io/run_file.h"

namespace softglass::micro {

/// `snapshots` in time order, all of the stationary part; radii in label order.
StructureRecord analyse_snapshots(std::span<const Snapshot> snapshots, std::span<const double> radius,
                                  double side, const ContactLaw& law, const StructureSettings& settings);

/// The snapshots of `result` from strain `from` on (the stationary part).
std::vector<Snapshot> stationary_snapshots(const ShearResult& result);

}  // namespace softglass::micro
