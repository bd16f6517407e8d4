// Result tables as CSV text: one header line with units in every column name,
// then rows. Numbers are written with 10 significant digits (more than any
// fitted value carries), text cells quoted when they hold a comma or a quote.
#pragma once

#include <string>
#include <vector>

namespace softglass::bridge {

class CsvWriter {
 public:
  /// `comments` become `#` lines above the header (provenance).
  CsvWriter(const std::vector<std::string>& comments, const std::vector<std::string>& header);

  /// NaN is written as `nan` (the cell does not apply); an infinity is a
  /// NumericalError naming the column.
  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(const std::string& text);
  /// Ends the row; the row must have as many cells as the header.
  void end_row();

  const std::string& text() const { return text_; }

 private:
  void separate();
  std::string text_;
  std::size_t columns_ = 0, cells_ = 0;
};

}  // namespace softglass::bridge
