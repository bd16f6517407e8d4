#include "common/unit_table.h"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"

namespace softglass {

namespace {

// Whether column `name` holds errors, which may be n/a (NaN): a standard error
// "_se", an "error" or an "error_..." column.
bool error_column(const std::string& name) {
  return name.ends_with("_se") || name.find("error") != std::string::npos;
}

}  // namespace

void require_finite_cells(const UnitTable& table, const std::string& file) {
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const double v = table.rows[r][c];
      if (std::isfinite(v) || (std::isnan(v) && error_column(table.columns[c].name))) continue;
      throw NumericalError(fmt::format(
          "{}: row {}, column '{}' came out as {}: a result that is not a finite number is not "
          "written",
          file, r + 1, table.columns[c].name, v));
    }
}

void write_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
               const std::vector<std::string>& comments, const UnitTable& table, int digits) {
  require_finite_cells(table, shown_path.string());
  write_file(path, shown_path.string(), [&](std::ostream& csv) {
    for (const std::string& line : comments) csv << "# " << line << "\n";
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      csv << (c ? "," : "") << table.columns[c].name << " [" << table.columns[c].unit << "]";
    csv << "\n";
    for (const auto& row : table.rows)
      csv << fmt::format("{:.{}g}\n", fmt::join(row, ","), digits);
  });
}

void write_columns(H5Group& group, const UnitTable& table) {
  require_finite_cells(table, "a table");
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    std::vector<double> column;
    for (const auto& row : table.rows) column.push_back(row[c]);
    group.write(table.columns[c].name, column, {}, {.units = table.columns[c].unit});
  }
}

}  // namespace softglass
