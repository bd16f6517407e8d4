// The table files of a `macro` run — results.csv/.h5 of `macro run`,
// comparison.csv/.h5 of `macro compare` (product.md: one HDF5 file per run,
// CSV with units in every header). The HDF5 file holds the CSV's table, one
// dataset per column, and the run's provenance:
//
//   /                  attributes software, scene_file, wall_time [s],
//                      mpi_ranks, ranks_per_point, operating_points
//   /description       what was computed: the scene (geometry, formulation,
//                      boundary conditions) and, for a comparison, the data
//   /model             material law and solver
//   /parameters        the full parameter set as read (ParameterHandler text)
//   /results/<column>  one 1-D dataset per column of the CSV, each with its
//                      `units`; the first is the operating point
//
// Readable by h5dump and h5py; the dataset names are the CSV's column names.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/atomic_output.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

struct RunProvenance {
  std::string software, scene_file, description, model, parameters;
  double wall_time = 0.0;
  unsigned mpi_ranks = 1, ranks_per_point = 1;
};

/// Writes the temporary file of `out`: each of `comments` as a `# ` line, the
/// header "name [unit]" per column, then `rows` with `digits` significant
/// digits; NumericalError naming the final path if it cannot be written.
void write_results_csv(const AtomicOutput& out, const std::vector<std::string>& comments,
                       const std::vector<Column>& columns,
                       const std::vector<std::vector<double>>& rows, int digits);

/// Writes `path` (a new file): column c of `rows` under the name of `columns[c]`.
void write_results_h5(const std::filesystem::path& path, const std::vector<Column>& columns,
                      const std::vector<std::vector<double>>& rows, const RunProvenance& run);

}  // namespace softglass::macro::app
