#include "common/unit_table.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/atomic_output.h"
#include "common/h5_file.h"

namespace softglass {

void write_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
               const std::vector<std::string>& comments, const UnitTable& table, int digits) {
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
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    std::vector<double> column;
    for (const auto& row : table.rows) column.push_back(row[c]);
    group.write(table.columns[c].name, column, {}, {.units = table.columns[c].unit});
  }
}

}  // namespace softglass
