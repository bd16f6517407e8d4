// A table of numbers whose every column carries its unit: the result tables
// the tools write, as CSV (docs/output.md: units in every header) and as one
// HDF5 dataset per column with its `units` attribute.
//
// CSV form: each comment line as "# line", the header "name [unit],...", then
// one line per row, each number with `digits` significant digits ({:.Ng}).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace softglass {

class H5Group;

/// A column: name and unit, written "name [unit]".
struct Column {
  std::string name;
  std::string unit;
};

struct UnitTable {
  std::vector<Column> columns;
  std::vector<std::vector<double>> rows;  ///< each as wide as `columns`
};

/// Every number a tool writes passes here: NumericalError naming `file`, the
/// row and the column of a cell that is not finite, except NaN in an error
/// column (name ending "_se" or holding "error"), which means "n/a" (an error
/// one packing cannot give).
void require_finite_cells(const UnitTable& table, const std::string& file);

/// Checks the cells (require_finite_cells) and writes `path` in the CSV form above; NumericalError naming `shown_path`
/// (the file the user will see, when `path` is a temporary) if it cannot.
void write_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
               const std::vector<std::string>& comments, const UnitTable& table, int digits);

/// Column c of the table as the 1-D dataset `group/<name of c>` with its units.
void write_columns(H5Group& group, const UnitTable& table);

}  // namespace softglass
