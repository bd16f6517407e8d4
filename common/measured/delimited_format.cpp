// `delimited`: any other table a spreadsheet or an instrument writes: tab,
// semicolon or comma between cells, decimal points or commas, lines of
// metadata ("Sample: ...") above the column names, and the units either in
// the names ("Shear rate [1/s]", "Stress (Pa)") or in a row of their own under
// them. The first row holding numbers starts the data; the row above it is
// the names, or the units when it reads as units (export_text.h). Tried last.
#include <fmt/format.h>

#include "common/errors.h"
#include "common/measured/export_format.h"

namespace softglass::measured {
namespace {

// A row of points: two numbers at least, and numbers in most of its cells
// (a status or sample column may hold text).
bool data_row(const std::vector<std::string>& cells) {
  std::size_t numbers = 0, filled = 0;
  for (const std::string& cell : cells) {
    if (cell.empty()) continue;
    ++filled;
    numbers += looks_numeric(cell);
  }
  return numbers >= 2 && 2 * numbers >= filled;
}

// Whether a row under the names holds their units: every cell bracketed or a
// unit the exports write, or, for units no list holds ("Pa.s²", "g/cm³"),
// short words without spaces beside one such unit at least, and no number.
bool units_row_like(const std::vector<std::string>& row) {
  bool all_known = true, one_known = false, all_short = true;
  for (const std::string& cell : row) {
    if (cell.empty()) continue;
    if (looks_numeric(cell)) return false;
    const bool known = looks_like_unit(cell);
    all_known = all_known && known;
    one_known = one_known || known;
    all_short = all_short && cell.size() <= 12 && cell.find(' ') == std::string::npos;
  }
  return one_known && (all_known || all_short);
}

// "Stress (Pa)" → "Stress [Pa]" when the part in parentheses reads as a unit.
std::string bracketed(const std::string& name) {
  const auto open = name.rfind('(');
  if (open == std::string::npos || !name.ends_with(')') || open == 0) return name;
  const std::string unit = name.substr(open);
  if (!looks_like_unit(unit)) return name;
  std::string head = name.substr(0, open);
  while (!head.empty() && head.back() == ' ') head.pop_back();
  return fmt::format("{} [{}]", head, bare_unit(unit));
}

MeasuredFile read(std::string_view, const std::vector<TextLine>& lines, const std::string& source) {
  std::vector<TextLine> table;
  for (const TextLine& l : lines)
    if (!l.text.starts_with('#')) table.push_back(l);
  const char delimiter = detect_delimiter(table);
  const std::string read_as = fmt::format("{} (read as a delimited table, {}-separated)", source,
                                          delimiter_name(delimiter));
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> numbers;
  for (const TextLine& l : table) {
    if (blank(l.text)) {
      cells.emplace_back();  // ends a block of points
    } else {
      cells.push_back(split_cells(l.text, delimiter, fmt::format("{}, line {}", source, l.number)));
    }
    numbers.push_back(l.number);
  }
  std::size_t first = 0;
  while (first < cells.size() && !data_row(cells[first])) ++first;
  if (first == cells.size()) {
    throw InputError(fmt::format(
        "{}: no row of numbers (two numbers or more, in most of its cells) was found", read_as));
  }
  std::size_t names = first;
  while (names > 0 && cells[names - 1].empty()) --names;
  if (names == 0) {
    throw InputError(fmt::format("{}, line {}: the numbers have no row of column names above them",
                                 read_as, numbers[first]));
  }
  --names;
  Section section;
  const bool units_row = names > 0 && units_row_like(cells[names]);
  if (units_row) {
    section.units = cells[names];
    --names;
  }
  section.names = cells[names];
  if (!units_row)
    for (std::string& name : section.names) name = bracketed(name);
  for (std::size_t r = 0; r < names; ++r) {
    std::string line;
    for (const std::string& cell : cells[r])
      if (!cell.empty()) line += (line.empty() ? "" : ": ") + cell;
    if (!line.empty()) section.comments.push_back(line);
  }
  std::size_t r = first;
  for (; r < cells.size() && data_row(cells[r]); ++r) {
    section.rows.push_back(cells[r]);
    section.lines.push_back(numbers[r]);
  }
  for (; r < cells.size(); ++r)
    if (data_row(cells[r])) {
      throw InputError(fmt::format(
          "{}, line {}: a second block of numbers, after the table that ends at line {}; "
          "export one table per file",
          read_as, numbers[r], section.lines.back()));
    }
  const Decimal decimal = detect_decimal(section.rows, section.lines, delimiter, read_as);
  MeasuredFile file{.source = source, .format = "delimited"};
  file.sections.push_back(section_table(source, std::move(section), decimal));
  return file;
}

}  // namespace

FormatEntry delimited_format() {
  return {"delimited",
          "tab-, ';'- or ','-separated, decimal points or commas, metadata lines above the "
          "column names, units in the names or in a row under them",
          [](const std::vector<TextLine>&) { return true; }, read};
}

}  // namespace softglass::measured
