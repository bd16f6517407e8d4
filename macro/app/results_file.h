// The HDF5 file of a `macro` run (product.md: one HDF5 file per run) —
// results.h5 of `macro run`, comparison.h5 of `macro compare`: the table of
// the run's CSV, one dataset per column, and the run's provenance.
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

#include "macro/scenes/scene.h"

namespace softglass::macro::app {

struct RunProvenance {
  std::string software, scene_file, description, model, parameters;
  double wall_time = 0.0;
  unsigned mpi_ranks = 1, ranks_per_point = 1;
};

/// A column's CSV header, "name [unit]".
std::string csv_header(const Column& column);

/// Writes `path` (a new file): column c of `rows` under the name of `columns[c]`.
void write_results_h5(const std::filesystem::path& path, const std::vector<Column>& columns,
                      const std::vector<std::vector<double>>& rows, const RunProvenance& run);

}  // namespace softglass::macro::app
