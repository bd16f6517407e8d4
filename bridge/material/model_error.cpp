#include "bridge/material/model_error.h"

#include <fmt/format.h>

#include "bridge/law/law.h"
#include "common/csv_table.h"
#include "common/errors.h"

namespace softglass::bridge {

std::optional<ModelError> read_model_error(const std::filesystem::path& law_file) {
  const std::filesystem::path file = beside(law_file, "_model_error.csv");
  if (!std::filesystem::exists(file)) return std::nullopt;
  const CsvTable csv = CsvTable::read(file);
  const auto column = [&csv](const char* name) {
    const auto c = csv.find(name);
    require(c.has_value(), fmt::format("{}: no column '{}'", csv.source(), name));
    return *c;
  };
  const std::size_t mode = column("mode"), form = column("law_form"), branch = column("branch"),
                    median = column("median_abs_error [1]"), bias = column("bias [1]"),
                    points = column("points [1]"), sets = column("data_sets");
  ModelError out;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const std::string& letter = csv.text(r, mode);
    require(letter.size() == 1 && letter[0] >= 'a' && letter[0] <= 'd',
            fmt::format("{}: mode '{}' is not one of a, b, c, d", csv.where(r, mode), letter));
    out[{letter[0], csv.text(r, form), csv.text(r, branch)}] = {
        .median_abs_error = csv.number(r, median),
        .bias = csv.number(r, bias),
        .points = int(csv.number(r, points)),
        .data_sets = csv.text(r, sets)};
  }
  return out;
}

}  // namespace softglass::bridge
