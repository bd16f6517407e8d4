// A table of numbers whose every column carries its unit: the result tables
// the tools write, as CSV (csv_writer.h: the header, a units line, comments,
// rows) and as one HDF5 dataset per column with its `units` attribute.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/csv_writer.h"

namespace softglass {

class H5Group;

struct UnitTable {
  std::vector<Column> columns;
  std::vector<std::vector<double>> rows;  ///< each as wide as `columns`
};

/// Writes `path` in the CSV form of csv_writer.h, each number with `digits`
/// significant digits, every cell checked there; NumericalError naming
/// `shown_path` (the file the user will see, when `path` is a temporary).
void write_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
               const std::vector<std::string>& comments, const UnitTable& table, int digits);

/// Column c of the table as the 1-D dataset `group/<name of c>` with its
/// units, every cell checked as for the CSV.
void write_columns(H5Group& group, const UnitTable& table);

}  // namespace softglass
