#include "common/measured/export_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <stdexcept>

#include "common/errors.h"
#include "common/measured/columns.h"

namespace softglass::measured {

namespace {

bool digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Whether `cell` is a number whose decimal separator, if any, is `separator`.
bool number_with(std::string_view cell, char separator) {
  std::size_t i = 0;
  if (i < cell.size() && (cell[i] == '+' || cell[i] == '-')) ++i;
  bool digits = false, separated = false;
  for (; i < cell.size(); ++i) {
    if (digit(cell[i])) {
      digits = true;
    } else if (cell[i] == separator && !separated) {
      separated = true;
    } else {
      break;
    }
  }
  if (!digits) return false;
  if (i == cell.size()) return true;
  if (cell[i] != 'e' && cell[i] != 'E') return false;
  ++i;
  if (i < cell.size() && (cell[i] == '+' || cell[i] == '-')) ++i;
  if (i == cell.size()) return false;
  for (; i < cell.size(); ++i)
    if (!digit(cell[i])) return false;
  return true;
}

bool has_separator(std::string_view cell, char separator) {
  return cell.find(separator) != std::string_view::npos;
}

// Units instrument exports write for columns no reader uses (times,
// temperatures, viscosities, angles, lengths): a row of them is a units row.
constexpr std::array kOtherUnits = {
    "s",    "min", "h",   "°C", "K",  "Pa.s", "Pa·s", "mPa.s", "mPa·s", "Pa s",  "mPa s", "rad",
    "mrad", "°",   "deg", "mm", "µm", "um",   "m",    "Hz",    "-",     "1/rad", "N",     "J/m³"};

}  // namespace

std::vector<TextLine> lines_of(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  std::vector<TextLine> lines;
  std::size_t number = 0;
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    if (line.ends_with('\r')) line.remove_suffix(1);
    lines.push_back({++number, line});
  }
  return lines;
}

bool blank(std::string_view line) {
  return line.find_first_not_of(" \t;,\r") == std::string_view::npos;
}

char detect_delimiter(const std::vector<TextLine>& lines) {
  std::size_t tabs = 0, semicolons = 0;
  for (const TextLine& l : lines) {
    tabs += has_separator(l.text, '\t');
    semicolons += has_separator(l.text, ';');
  }
  return tabs > 0 ? '\t' : semicolons > 0 ? ';' : ',';
}

std::string delimiter_name(char delimiter) {
  return delimiter == '\t' ? std::string("tab") : fmt::format("'{}'", delimiter);
}

bool is_number(std::string_view cell, Decimal decimal) {
  return number_with(cell, decimal == Decimal::comma ? ',' : '.');
}

bool looks_numeric(std::string_view cell) {
  if (number_with(cell, '.') || number_with(cell, ',')) return true;
  if (!has_separator(cell, '.') || !has_separator(cell, ',')) return false;
  for (const char thousands : {'.', ','}) {
    std::string bare(cell);
    std::erase(bare, thousands);
    if (number_with(bare, thousands == '.' ? ',' : '.')) return true;
  }
  return false;
}

Decimal detect_decimal(const std::vector<std::vector<std::string>>& rows,
                       const std::vector<std::size_t>& lines, char delimiter,
                       const std::string& source) {
  if (delimiter == ',') return Decimal::point;
  std::size_t comma_line = 0, point_line = 0;
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const std::string& cell : rows[r]) {
      if (!comma_line && has_separator(cell, ',') && number_with(cell, ',')) comma_line = lines[r];
      if (!point_line && has_separator(cell, '.') && number_with(cell, '.')) point_line = lines[r];
    }
  if (comma_line && point_line) {
    throw InputError(fmt::format(
        "{}: numbers are written with decimal commas (line {}) and with decimal points (line "
        "{}); export the file with one decimal separator",
        source, comma_line, point_line));
  }
  return comma_line ? Decimal::comma : Decimal::point;
}

bool looks_like_unit(std::string_view cell) {
  if (cell.size() >= 2 &&
      ((cell.front() == '[' && cell.back() == ']') || (cell.front() == '(' && cell.back() == ')')))
    return true;
  const std::string unit(cell);
  return known_unit(unit) ||
         std::find(kOtherUnits.begin(), kOtherUnits.end(), unit) != kOtherUnits.end();
}

std::string bare_unit(std::string_view cell) {
  if (cell.size() >= 2 &&
      ((cell.front() == '[' && cell.back() == ']') || (cell.front() == '(' && cell.back() == ')')))
    cell = cell.substr(1, cell.size() - 2);
  return std::string(cell);
}

CsvTable section_table(const std::string& source, Section section, Decimal decimal) {
  std::vector<std::string> header;
  for (std::size_t c = 0; c < section.names.size(); ++c) {
    const std::string unit = c < section.units.size() ? bare_unit(section.units[c]) : "";
    header.push_back(unit.empty() ? section.names[c]
                                  : fmt::format("{} [{}]", section.names[c], unit));
  }
  const char separator = decimal == Decimal::comma ? ',' : '.';
  const char thousands = decimal == Decimal::comma ? '.' : ',';
  for (std::size_t r = 0; r < section.rows.size(); ++r) {
    std::vector<std::string>& row = section.rows[r];
    if (row.size() > header.size()) {
      throw InputError(fmt::format("{}, line {}: {} cells where the column names have {}", source,
                                   section.lines[r], row.size(), header.size()));
    }
    row.resize(header.size());
    for (std::string& cell : row) {
      if (is_number(cell, decimal)) {
        std::replace(cell.begin(), cell.end(), separator, '.');
      } else if (has_separator(cell, thousands) && has_separator(cell, separator)) {
        std::string bare = cell;
        std::erase(bare, thousands);
        if (is_number(bare, decimal)) {
          throw InputError(fmt::format(
              "{}, line {}: '{}' is written with a thousands separator, which is not read "
              "('{}' alone would be ambiguous); export numbers without one",
              source, section.lines[r], cell, thousands));
        }
      }
    }
  }
  return CsvTable::from_rows(source, std::move(section.title), std::move(section.comments),
                             std::move(header), std::move(section.rows), std::move(section.lines));
}

}  // namespace softglass::measured
