// `plain`: the comma-separated form softglass documents (docs/flow-curve-format.md):
// `#` comment lines, a header whose names carry their units in brackets, then
// one row of numbers per point. Recognised by a first row of names without
// tabs or semicolons followed directly by a row of numbers.
#include "common/errors.h"
#include "common/measured/export_format.h"

namespace softglass::measured {
namespace {

bool recognises(const std::vector<TextLine>& lines) {
  std::vector<std::string_view> rows;
  for (const TextLine& l : lines) {
    if (blank(l.text) || l.text.starts_with('#')) continue;
    rows.push_back(l.text);
    if (rows.size() == 2) break;
  }
  if (rows.empty()) return false;
  for (std::string_view row : rows)
    if (row.find_first_of("\t;") != std::string_view::npos) return false;
  if (rows.size() < 2) return true;  // a header alone: the plain reader says what is missing
  try {
    for (const std::string& cell : split_cells(rows[1], ',', ""))
      if (!cell.empty() && !is_number(cell, Decimal::point)) return false;
  } catch (const InputError&) {  // an unterminated quote: the plain reader names its line
  }
  return true;
}

MeasuredFile read(std::string_view text, const std::vector<TextLine>&, const std::string& source) {
  MeasuredFile file{.source = source, .format = "plain"};
  file.sections.push_back(CsvTable::parse(text, source));
  return file;
}

}  // namespace

FormatEntry plain_format() {
  return {"plain", "comma-separated, '#' comments, names with units in brackets", recognises, read};
}

}  // namespace softglass::measured
