#include "common/csv_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "common/csv_table.h"
#include "common/errors.h"

namespace softglass {

namespace {

// A text cell, quoted when it holds a comma or a quote ("" inside).
std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<Column> columns_of(const std::vector<std::string>& header) {
  std::vector<Column> columns;
  for (const std::string& h : header) {
    ColumnName c = split_units(h);
    columns.push_back({std::move(c.name), std::move(c.units)});
  }
  return columns;
}

}  // namespace

bool error_column(const Column& c) {
  return c.name.ends_with("_se") || c.name.find("error") != std::string::npos;
}

void check_cell(const Column& c, double value, const std::string& table, std::size_t row) {
  const bool na = std::isnan(value) && (c.may_be_na || error_column(c));
  if (!std::isfinite(value) && !na) {
    throw NumericalError(fmt::format(
        "{}: row {}, column '{}' came out as {}: a result that is not a finite number is not "
        "written",
        table, row, c.name, value));
  }
  if (c.name.ends_with("_se") && value < 0) {
    throw NumericalError(
        fmt::format("{}: row {}, column '{}' came out as {}: a standard error is not negative",
                    table, row, c.name, value));
  }
}

CsvWriter::CsvWriter(std::string table, std::vector<Column> columns,
                     const std::vector<std::string>& comments, int digits)
    : table_(std::move(table)), columns_(std::move(columns)), digits_(digits) {
  std::string units;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    text_ += (c ? "," : "") + csv_text(columns_[c].name);
    units += (c ? "," : "") + columns_[c].unit;
  }
  text_ += "\n# units: " + units + "\n";
  for (const std::string& line : comments) text_ += "# " + line + "\n";
}

CsvWriter::CsvWriter(std::string table, const std::vector<std::string>& header,
                     const std::vector<std::string>& comments, int digits)
    : CsvWriter(std::move(table), columns_of(header), comments, digits) {}

void CsvWriter::may_be_na(const std::string& name) {
  for (Column& c : columns_)
    if (c.name == name) c.may_be_na = true;
}

void CsvWriter::separate() {
  if (cells_ >= columns_.size())
    throw std::logic_error(
        fmt::format("{}: a row wider than its {} columns", table_, columns_.size()));
  if (cells_++ > 0) text_ += ',';
}

CsvWriter& CsvWriter::operator<<(double value) {
  separate();  // refuses a row wider than the columns
  check_cell(columns_[cells_ - 1], value, table_, rows_ + 1);
  text_ += fmt::format("{:.{}g}", value, digits_);
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& text) {
  separate();
  text_ += csv_text(text);
  return *this;
}

void CsvWriter::end_row() {
  if (cells_ != columns_.size()) {
    throw std::logic_error(
        fmt::format("{}: a row of {} cells under {} columns", table_, cells_, columns_.size()));
  }
  text_ += '\n';
  cells_ = 0;
  ++rows_;
}

}  // namespace softglass
