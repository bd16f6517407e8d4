#include "common/unit_table.h"

#include "common/atomic_output.h"
#include "common/h5_file.h"

namespace softglass {

void write_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
               const std::vector<std::string>& comments, const UnitTable& table, int digits) {
  CsvWriter csv(shown_path.string(), table.columns, comments, digits);
  for (const auto& row : table.rows) {
    for (const double v : row) csv << v;
    csv.end_row();
  }
  write_file(path, shown_path.string(), [&](std::ostream& out) { out << csv.text(); });
}

void write_columns(H5Group& group, const UnitTable& table) {
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      check_cell(table.columns[c], table.rows[r][c], "a table", r + 1);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    std::vector<double> column;
    for (const auto& row : table.rows) column.push_back(row[c]);
    group.write(table.columns[c].name, column, {}, {.units = table.columns[c].unit});
  }
}

}  // namespace softglass
