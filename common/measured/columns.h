// What the layouts of measured files (layout.h) share: the columns they
// recognise by name (measured_curves.h lists them), the units each may carry
// and their factors to SI, the checked reading of one cell, and the finishing
// of a file's curves (sorted, at least 4 points each).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/csv_table.h"
#include "common/measured_curves.h"

namespace softglass::measured {

/// What a recognised column holds: its names, its units, whether it must be
/// positive and whether the command line's fallback units apply.
struct Kind {
  Measured quantity;
  std::vector<std::string> names;
  const std::map<std::string, double>* units;
  const char* unit_kind;
  bool positive;
  enum class Fallback { none, rate, stress } fallback;
};

/// The kind of the column named `name` (case, '_', '-' and spaces aside), or nullptr.
const Kind* kind_of(const std::string& name);
/// Whether `name` labels curves ("sample", "curve", ...).
bool is_label(const std::string& name);
/// "Stress [Pa]" or "stress_Pa" → {"Stress", "Pa"}; the suffix form only for known units.
ColumnName measured_name(const std::string& header);
/// Whether `unit` is a unit of some recognised column (spaces, "·" and "Nm"
/// written as for the factors).
bool known_unit(const std::string& unit);
/// The SI factor of `unit` for a column of kind `kind`; InputError naming `what` otherwise.
double unit_factor(const Kind& kind, const std::string& unit, const std::string& what);

/// A column being read: where it is, its factor to SI, its sign rule.
struct Column {
  std::size_t index = 0;
  double factor = 1.0;
  bool positive = true;
};

/// The value of row `row` in column `c`, checked and in SI units.
double value(const CsvTable& csv, std::size_t row, const Column& c);

/// Sorts every column of each curve by the abscissa; InputError for a curve
/// of fewer than 4 points.
void finish(std::vector<RheometerCurve>& curves, const std::string& source);

}  // namespace softglass::measured
