#include "common/csv_table.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/errors.h"
#include "common/input_file.h"

namespace softglass {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

}  // namespace

std::vector<std::string> split_cells(std::string_view line, char delimiter,
                                     const std::string& where) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == delimiter) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  if (quoted) throw InputError(where + ": unterminated quote");
  for (auto& cell : cells) cell = std::string(trim(cell));
  return cells;
}

CsvTable CsvTable::read(const std::filesystem::path& file) {
  return parse(read_input_text(file, "table"), file.string());
}

CsvTable CsvTable::parse(std::string_view text, std::string source) {
  CsvTable table;
  table.source_ = std::move(source);
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  std::size_t number = 0;
  while (!text.empty()) {
    const auto end = text.find('\n');
    const std::string_view raw = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++number;
    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      const std::string_view comment = trim(line.substr(1));
      if (!table.header_.empty() && table.cells_.empty() && comment.starts_with("units:")) {
        table.attach_units(comment.substr(6), number);
      } else if (table.cells_.empty()) {
        table.comments_.emplace_back(comment);
      }
      continue;
    }
    const std::string where = fmt::format("{}, line {}", table.source_, number);
    auto cells = split_cells(line, ',', where);
    if (table.header_.empty()) {
      table.header_ = std::move(cells);
      continue;
    }
    if (cells.size() != table.header_.size()) {
      throw InputError(fmt::format("{}: {} cells where the header has {}", where, cells.size(),
                                   table.header_.size()));
    }
    table.cells_.push_back(std::move(cells));
    table.lines_.push_back(number);
  }
  if (table.header_.empty()) throw InputError(table.source_ + ": no header line");
  return table;
}

void CsvTable::attach_units(std::string_view units, std::size_t line) {
  const std::string where = fmt::format("{}, line {}", source_, line);
  const std::vector<std::string> cells = split_cells(units, ',', where);
  if (cells.size() != header_.size()) {
    throw InputError(fmt::format("{}: {} units for the header's {} columns", where, cells.size(),
                                 header_.size()));
  }
  for (std::size_t c = 0; c < header_.size(); ++c) {
    if (cells[c].empty()) continue;
    if (!split_units(header_[c]).units.empty()) {
      throw InputError(
          fmt::format("{}: column '{}' has its units in the header and in the units "
                      "line",
                      where, header_[c]));
    }
    header_[c] = fmt::format("{} [{}]", header_[c], cells[c]);
  }
}

CsvTable CsvTable::from_rows(std::string source, std::string title,
                             std::vector<std::string> comments, std::vector<std::string> header,
                             std::vector<std::vector<std::string>> rows,
                             std::vector<std::size_t> lines) {
  CsvTable table;
  table.source_ = std::move(source);
  table.title_ = std::move(title);
  table.comments_ = std::move(comments);
  table.header_ = std::move(header);
  table.cells_ = std::move(rows);
  table.lines_ = std::move(lines);
  for (const auto& row : table.cells_)
    if (row.size() != table.header_.size())
      throw std::logic_error("CsvTable::from_rows: a row as wide as the header was expected");
  return table;
}

std::string CsvTable::where(std::size_t row, std::size_t column) const {
  return fmt::format("{}, line {}, column '{}'", source_, lines_[row], header_[column]);
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  const std::string& cell = cells_[row][column];
  if (cell.empty()) throw InputError(where(row, column) + ": empty (missing values are refused)");
  double value = 0.0;
  const char* begin = cell.data();
  const char* end = begin + cell.size();
  if (*begin == '+') ++begin;  // from_chars refuses a leading '+'
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end) {
    throw InputError(fmt::format("{}: '{}' is not a number", where(row, column), cell));
  }
  if (!std::isfinite(value)) {
    throw InputError(fmt::format("{}: '{}' is not finite", where(row, column), cell));
  }
  return value;
}

std::optional<std::size_t> CsvTable::find(std::string_view name) const {
  for (std::size_t c = 0; c < header_.size(); ++c)
    if (header_[c] == name) return c;
  return std::nullopt;
}

ColumnName split_units(std::string_view header) {
  header = trim(header);
  const auto open = header.rfind('[');
  if (open == std::string_view::npos || !header.ends_with(']')) return {std::string(header), ""};
  return {std::string(trim(header.substr(0, open))),
          std::string(trim(header.substr(open + 1, header.size() - open - 2)))};
}

}  // namespace softglass
