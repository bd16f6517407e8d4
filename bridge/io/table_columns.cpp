#include "bridge/io/table_columns.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"

namespace softglass::bridge {

namespace {
std::string without_spaces(std::string s) {
  std::erase(s, ' ');
  return s;
}
}  // namespace

TableColumns::TableColumns(const CsvTable& csv, std::string (*unit_of)(std::string_view),
                           std::string format, std::string units_rule)
    : csv_(csv), unit_of_(unit_of), format_(std::move(format)) {
  for (std::size_t c = 0; c < csv.columns(); ++c) {
    const ColumnName column = split_units(csv.header()[c]);
    if (column.units.empty()) {
      throw InputError(fmt::format(
          "{}: column '{}' has no units; every column names its units in brackets, e.g. "
          "'sigma [E*]' ({})",
          csv.source(), csv.header()[c], format_));
    }
    const std::string expected = unit_of_(column.name);
    if (!expected.empty() && without_spaces(column.units) != expected) {
      throw InputError(fmt::format("{}: column '{}' is in '{}', expected '{}': {}", csv.source(),
                                   csv.header()[c], column.units, expected, units_rule));
    }
    if (!index_.emplace(column.name, c).second)
      throw InputError(fmt::format("{}: column '{}' appears twice", csv.source(), column.name));
  }
  // Every cell must be a finite number (the formats allow no missing values).
  for (std::size_t r = 0; r < csv.rows(); ++r)
    for (std::size_t c = 0; c < csv.columns(); ++c) csv.number(r, c);
}

std::optional<std::size_t> TableColumns::find(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? std::nullopt : std::optional(it->second);
}

std::size_t TableColumns::require(const std::string& name) const {
  const auto c = find(name);
  if (!c)
    throw InputError(fmt::format("{}: column '{} [{}]' is missing ({})", csv_.source(), name,
                                 unit_of_(name), format_));
  return *c;
}

double TableColumns::positive(std::size_t r, std::size_t c) const {
  return value(
      r, c, [](double v) { return v > 0; }, "> 0");
}

double TableColumns::nonnegative(std::size_t r, std::size_t c) const {
  return value(
      r, c, [](double v) { return v >= 0; }, ">= 0");
}

double TableColumns::fraction(std::size_t r, std::size_t c) const {
  return value(
      r, c, [](double v) { return v > 0 && v < 1; }, "in (0, 1)");
}

double TableColumns::count(std::size_t r, std::size_t c, double least) const {
  return value(
      r, c, [&](double v) { return v >= least && v == std::floor(v) && v < 1e15; },
      least > 0 ? "a whole number >= 1" : "a whole number >= 0");
}

void TableColumns::refuse(std::size_t r, std::size_t c, double v, const char* rule) const {
  throw InputError(fmt::format("{}: {} (must be {})", csv_.where(r, c), v, rule));
}

}  // namespace softglass::bridge
