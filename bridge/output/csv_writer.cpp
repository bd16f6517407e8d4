#include "bridge/output/csv_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

CsvWriter::CsvWriter(const std::vector<std::string>& comments,
                     const std::vector<std::string>& header)
    : columns_(header.size()) {
  for (const std::string& line : comments) text_ += "# " + line + "\n";
  for (const std::string& name : header) *this << name;
  end_row();
}

void CsvWriter::separate() {
  if (cells_++ > 0) text_ += ',';
}

CsvWriter& CsvWriter::operator<<(double value) {
  // NaN marks a cell that does not apply (a phi without its quasi-static row,
  // an error one packing cannot give); an infinity is never a result.
  if (std::isinf(value)) {
    throw NumericalError(fmt::format("a result table's column {} (of {}) came out as {}: not "
                                     "written",
                                     cells_ + 1, columns_, value));
  }
  separate();
  text_ += fmt::format("{:.10g}", value);
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& text) {
  separate();
  text_ += quoted(text);
  return *this;
}

void CsvWriter::end_row() {
  if (cells_ != columns_) {
    throw std::logic_error(fmt::format("CSV row with {} cells under {} columns", cells_, columns_));
  }
  text_ += '\n';
  cells_ = 0;
}

}  // namespace softglass::bridge
