#include "macro/app/results_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>

#include "common/errors.h"
#include "common/h5_file.h"

namespace softglass::macro::app {

void write_results_csv(const AtomicOutput& out, const std::vector<std::string>& comments,
                       const std::vector<Column>& columns,
                       const std::vector<std::vector<double>>& rows, int digits) {
  std::ofstream csv(out.temporary_path());
  for (const std::string& line : comments) csv << "# " << line << "\n";
  for (std::size_t c = 0; c < columns.size(); ++c)
    csv << (c ? "," : "") << columns[c].name << " [" << columns[c].unit << "]";
  csv << "\n";
  for (const auto& row : rows) csv << fmt::format("{:.{}g}\n", fmt::join(row, ","), digits);
  csv.close();
  if (!csv) throw NumericalError(fmt::format("cannot write {}", out.final_path().string()));
}

void write_results_h5(const std::filesystem::path& path, const std::vector<Column>& columns,
                      const std::vector<std::vector<double>>& rows, const RunProvenance& run) {
  H5File file = H5File::create(path);
  H5Group root = file.root();
  root.set_attribute("software", run.software);
  root.set_attribute("scene_file", run.scene_file);
  root.set_attribute("wall_time", run.wall_time);
  root.set_attribute("mpi_ranks", run.mpi_ranks);
  root.set_attribute("ranks_per_point", run.ranks_per_point);
  root.set_attribute("operating_points", rows.size());
  root.write_string("description", run.description);
  root.write_string("model", run.model);
  root.write_string("parameters", run.parameters);
  H5Group results = root.create_group("results");
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::vector<double> column;
    for (const auto& row : rows) column.push_back(row[c]);
    results.write(columns[c].name, column, {}, {.units = columns[c].unit});
  }
  file.close();
}

}  // namespace softglass::macro::app
