#include "micro/io/structure_csv.h"

#include <fmt/format.h>

#include "common/csv_writer.h"

namespace softglass::micro {

StructureCsv::StructureCsv(const std::string& prefix, bool force)
    : harmonics_(prefix + "_harmonics.csv", force),
      map_(prefix + "_map.csv", force),
      summary_(prefix + "_summary.csv", force) {}

void StructureCsv::write(const StructureRecord& record) {
  const StructureResult& s = record.result;
  std::vector<std::string> header = {"r [R]"};
  for (const char* name : kHarmonicNames) {
    header.push_back(fmt::format("{} [1]", name));
    header.push_back(fmt::format("{}_error [1]", name));
  }
  for (const char* name : kHarmonicNames) {
    header.push_back(fmt::format("f{} [E* R^2]", name));
    header.push_back(fmt::format("f{}_error [E* R^2]", name));
  }
  CsvWriter harmonics(harmonics_.final_path().string(), header, {});
  for (std::size_t b = 0; b < s.r.size(); ++b) {
    harmonics << s.r[b];
    for (int h = 0; h < 6; ++h) harmonics << s.g[h][b] << s.g_error[h][b];
    for (int h = 0; h < 6; ++h) harmonics << s.fg[h][b] << s.fg_error[h][b];
    harmonics.end_row();
  }
  harmonics_.write_and_commit([&](std::ostream& f) { f << harmonics.text(); });

  CsvWriter map(map_.final_path().string(), {"r [R]", "theta [rad]", "g [1]"},
                {fmt::format("g(r, theta), pairs with |dz| < {} R", s.settings.slab)});
  for (std::size_t b = 0; b < s.map_r.size(); ++b)
    for (std::size_t t = 0; t < s.map_theta.size(); ++t) {
      map << s.map_r[b] << s.map_theta[t] << s.map[b * s.map_theta.size() + t];
      map.end_row();
    }
  map_.write_and_commit([&](std::ostream& f) { f << map.text(); });

  // One row per quantity, each in its own units (the last column).
  CsvWriter summary(summary_.final_path().string(),
                    {"quantity", "value", "standard_error", "units"},
                    {fmt::format("{} snapshots, strain {:.3f} to {:.3f}", s.snapshots,
                                 record.strain_from, record.strain_to)});
  for (const NamedEstimate& e : named_estimates(s)) {
    summary << e.name << e.estimate.value << e.estimate.error << e.units;
    summary.end_row();
  }
  summary_.write_and_commit([&](std::ostream& f) { f << summary.text(); });
}

}  // namespace softglass::micro
