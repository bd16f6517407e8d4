// The header of a table in reduced units (the flow-curve and oscillation
// tables micro writes): column names mapped to indices, every column's units
// checked against its format, every cell a finite number, and checked reads of
// one cell by the rule its column follows.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "common/csv_table.h"

namespace softglass::bridge {

class TableColumns {
 public:
  /// `unit_of(name)` is the format's unit of a column ("" for a column it does
  /// not define, which is then taken as it is); `format` names its page in
  /// messages, `units_rule` says what a wrong unit breaks.
  TableColumns(const CsvTable& csv, std::string (*unit_of)(std::string_view), std::string format,
               std::string units_rule);

  std::optional<std::size_t> find(const std::string& name) const;
  /// The column `name`; InputError naming it and its unit when it is missing.
  std::size_t require(const std::string& name) const;

  double number(std::size_t r, std::size_t c) const { return csv_.number(r, c); }
  /// The value of row r in column c, checked by `valid`; `rule` says what is allowed.
  template <class Valid>
  double value(std::size_t r, std::size_t c, Valid valid, const char* rule) const {
    const double v = csv_.number(r, c);
    if (!valid(v)) refuse(r, c, v, rule);
    return v;
  }
  double positive(std::size_t r, std::size_t c) const;
  double nonnegative(std::size_t r, std::size_t c) const;
  /// γ̃: positive, or 0 for the quasi-static limit (a sweep's AQS rows).
  double rate(std::size_t r, std::size_t c) const { return nonnegative(r, c); }
  double fraction(std::size_t r, std::size_t c) const;
  double count(std::size_t r, std::size_t c, double least) const;

 private:
  [[noreturn]] void refuse(std::size_t r, std::size_t c, double v, const char* rule) const;

  const CsvTable& csv_;
  std::string (*unit_of_)(std::string_view);
  std::string format_;
  std::map<std::string, std::size_t> index_;
};

}  // namespace softglass::bridge
