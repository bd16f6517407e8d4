#include "macro/app/results_file.h"

#include "common/h5_file.h"

namespace softglass::macro::app {

void write_results_csv(const AtomicOutput& out, const std::vector<std::string>& comments,
                       const UnitTable& table, int digits) {
  write_csv(out.temporary_path(), out.final_path(), comments, table, digits);
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
