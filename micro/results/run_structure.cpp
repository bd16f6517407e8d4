#include "micro/results/run_structure.h"

#include <fmt/format.h>

#include "common/errors.h"

namespace softglass::micro {

StructureRecord analyse_snapshots(std::span<const Snapshot> snapshots, std::span<const double> radius,
                                  double side, const ContactLaw& law, const StructureSettings& settings) {
  settings.validate();
  require(snapshots.size() >= 2,
          fmt::format("structure analysis needs at least 2 snapshots of the stationary part, has {}",
                      snapshots.size()));
  std::vector<StructureSample> samples(snapshots.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    LeesEdwardsBox box(side);
    box.set_strain(snapshots[k].strain);
    samples[k] = sample_structure(box, snapshots[k].position, radius, law, settings);
  }
  return {average_structure(samples, radius.size(), side * side * side, law, settings),
          snapshots.front().strain, snapshots.back().strain};
}

std::vector<Snapshot> stationary_snapshots(const ShearResult& result) {
  const double from = result.series.strain.front() + result.summary.transient_strain;
  std::vector<Snapshot> out;
  for (const Snapshot& s : result.snapshots)
    if (s.strain >= from - 1e-9) out.push_back(s);
  return out;
}

}  // namespace softglass::micro
