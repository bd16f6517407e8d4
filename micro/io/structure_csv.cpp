#include "micro/io/structure_csv.h"

#include <fmt/format.h>

namespace softglass::micro {

StructureCsv::StructureCsv(const std::string& prefix, bool force)
    : harmonics_(prefix + "_harmonics.csv", force),
      map_(prefix + "_map.csv", force),
      summary_(prefix + "_summary.csv", force) {}

void StructureCsv::write(const StructureRecord& record) {
  const StructureResult& s = record.result;
  harmonics_.write_and_commit([&](std::ostream& f) {
    f << "r [R]";
    for (const char* name : kHarmonicNames) f << "," << name << " [1]," << name << "_error [1]";
    for (const char* name : kHarmonicNames) f << ",f" << name << " [E* R^2],f" << name << "_error [E* R^2]";
    f << "\n";
    for (std::size_t b = 0; b < s.r.size(); ++b) {
      f << fmt::format("{:.6g}", s.r[b]);
      for (int h = 0; h < 6; ++h) f << fmt::format(",{:.8e},{:.3e}", s.g[h][b], s.g_error[h][b]);
      for (int h = 0; h < 6; ++h) f << fmt::format(",{:.8e},{:.3e}", s.fg[h][b], s.fg_error[h][b]);
      f << "\n";
    }
  });
  map_.write_and_commit([&](std::ostream& f) {
    f << fmt::format("# g(r, theta), pairs with |dz| < {} R\n", s.settings.slab);
    f << "r [R],theta [rad],g [1]\n";
    for (std::size_t b = 0; b < s.map_r.size(); ++b)
      for (std::size_t t = 0; t < s.map_theta.size(); ++t)
        f << fmt::format("{:.6g},{:.6g},{:.6e}\n", s.map_r[b], s.map_theta[t], s.map[b * s.map_theta.size() + t]);
  });
  summary_.write_and_commit([&](std::ostream& f) {
    f << fmt::format("# {} snapshots, strain {:.3f} to {:.3f}\n", s.snapshots, record.strain_from,
                     record.strain_to);
    f << "quantity,value,standard_error,units\n";
    for (const NamedEstimate& e : named_estimates(s))
      f << fmt::format("{},{:.8e},{:.3e},{}\n", e.name, e.estimate.value, e.estimate.error, e.units);
  });
}

}  // namespace softglass::micro
