#include "macro/app/results_file.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"
#include "common/h5_file.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

namespace {

// A solve that returned inf or NaN (the input check, input_scales.h, keeps
// the scales representable; a result can still overflow) must not become a
// table that looks like a result.
void require_finite(const UnitTable& table, const std::string& name) {
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const double v = table.rows[r][c];
      if (std::isfinite(v) || (std::isnan(v) && table.columns[c].name == kUndefinedWhereIdealIsZero))
        continue;
      throw NumericalError(fmt::format(
          "{} not written: {} = {} [{}] at {} = {} [{}] (row {}) is not a finite number",
          name, table.columns[c].name, v, table.columns[c].unit, table.columns[0].name,
          table.rows[r][0], table.columns[0].unit, r + 1));
    }
  }
}

}  // namespace

void write_results_csv(const std::filesystem::path& temporary, const std::filesystem::path& shown,
                       const std::vector<std::string>& comments, const UnitTable& table,
                       int digits) {
  require_finite(table, shown.string());
  write_csv(temporary, shown, comments, table, digits);
}

void write_results_h5(const std::filesystem::path& path, const UnitTable& table,
                      const RunProvenance& run) {
  H5File file = H5File::create(path);
  H5Group root = file.root();
  root.set_attribute("software", run.software);
  root.set_attribute("scene_file", run.scene_file);
  root.set_attribute("wall_time", run.wall_time);
  root.set_attribute("mpi_ranks", run.mpi_ranks);
  root.set_attribute("ranks_per_point", run.ranks_per_point);
  root.set_attribute("operating_points", table.rows.size());
  root.write_string("description", run.description);
  root.write_string("model", run.model);
  root.write_string("parameters", run.parameters);
  H5Group results = root.create_group("results");
  write_columns(results, table);
  file.close();
}

}  // namespace softglass::macro::app
