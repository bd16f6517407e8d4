// The one form of every result table the tools write as CSV, which numpy's
// `genfromtxt(f, delimiter=',', names=True, comments='#')` and pandas'
// `read_csv(f, comment='#')` load as they are, and CsvTable reads back:
//
//     phi,sigma,sigma_se,curve            the header: bare names, first line
//     # units: 1,E*,E*,                   each column's unit ("" for text)
//     # <provenance and notes>            comment lines
//     0.8,0.00123,1.2e-05,A               one row per line
//
// Every number passes one check here: a value that is not finite is a
// NumericalError naming the table, the row and the column, except NaN in a
// column that may be n/a — an error column (name ending "_se" or holding
// "error": one packing gives no scatter) or one the table declares so (a
// quasi-static value a φ has not) — written `nan`. A standard error ("_se")
// is never negative. Text cells are quoted when they hold a comma or a quote.
#pragma once

#include <string>
#include <vector>

namespace softglass {

/// A column: name and unit ("" for a text column); `may_be_na`: NaN is
/// allowed (written `nan`) beyond the error columns.
struct Column {
  std::string name;
  std::string unit;
  bool may_be_na = false;
};

/// Whether `c` holds errors, which may be n/a: a standard error "_se", an
/// "error" or an "error_..." column.
bool error_column(const Column& c);

/// The check every written number passes (above); NumericalError naming
/// `table`, the row (1-based) and the column otherwise.
void check_cell(const Column& c, double value, const std::string& table, std::size_t row);

class CsvWriter {
 public:
  /// `table` names the table in messages (its file); `comments` become the
  /// `#` lines under the units; numbers keep `digits` significant digits.
  CsvWriter(std::string table, std::vector<Column> columns,
            const std::vector<std::string>& comments, int digits = 10);
  /// The same with columns written "name [unit]" ("name" for a text column).
  CsvWriter(std::string table, const std::vector<std::string>& header,
            const std::vector<std::string>& comments, int digits = 10);

  /// Allows NaN in the column called `name` (a value that may not apply).
  void may_be_na(const std::string& name);

  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(const std::string& text);
  /// Ends the row; the row must have as many cells as there are columns.
  void end_row();

  const std::string& text() const { return text_; }

 private:
  void separate();
  std::string table_, text_;
  std::vector<Column> columns_;
  int digits_;
  std::size_t cells_ = 0, rows_ = 0;
};

}  // namespace softglass
