// The table files of a `macro` run — results.csv/.h5 of `macro run`,
// comparison.csv/.h5 of `macro compare` (docs/output.md: one HDF5 file per
// run, CSV with units in every header). The HDF5 file holds the CSV's table,
// one dataset per column (common/unit_table.h), and the run's provenance:
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

#include "common/unit_table.h"

namespace softglass::macro::app {

struct RunProvenance {
  std::string software, scene_file, description, model, parameters;
  double wall_time = 0.0;
  unsigned mpi_ranks = 1, ranks_per_point = 1;
};

/// Writes `temporary` (common/unit_table.h's CSV form, numbers with `digits`
/// significant digits), to become the file `shown`. Every number must be
/// finite (NaN only in kUndefinedWhereIdealIsZero, scenes/scene.h): otherwise NumericalError
/// naming the file, the column, the row and its operating point, and nothing
/// is written. NumericalError naming `shown` if it cannot be written.
void write_results_csv(const std::filesystem::path& temporary, const std::filesystem::path& shown,
                       const std::vector<std::string>& comments, const UnitTable& table,
                       int digits);

/// Writes `path` (a new file): the provenance, and the table under /results.
void write_results_h5(const std::filesystem::path& path, const UnitTable& table,
                      const RunProvenance& run);

}  // namespace softglass::macro::app
