// What the export formats (export_format.h) share: the file as numbered
// lines, the delimiter and the decimal separator of its tables, the units row,
// and the assembling of a section into the plain CSV's form (names with
// bracketed units, numbers with decimal points).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "common/csv_table.h"

namespace softglass::measured {

/// A line of the file, without its line break; `number` counts from 1.
struct TextLine {
  std::size_t number;
  std::string_view text;
};
/// The lines of `text` (a UTF-8 byte-order mark dropped, "\r\n" read as "\n").
std::vector<TextLine> lines_of(std::string_view text);

/// Whether a line holds nothing but spaces and delimiters (a spreadsheet's
/// empty row is ";;;;").
bool blank(std::string_view line);

/// The delimiter of an export's table: a tab where its lines hold tabs, else a
/// semicolon where they hold semicolons, else a comma.
char detect_delimiter(const std::vector<TextLine>& lines);
/// "tab", "';'", "','": the delimiter in messages.
std::string delimiter_name(char delimiter);

/// How the numbers of a table are written.
enum class Decimal { point, comma };

/// Whether `cell` is a number written with that decimal separator ("1,5e-3"
/// with a comma, "1.5e-3" with a point; digits alone in either).
bool is_number(std::string_view cell, Decimal decimal);
/// Whether `cell` is written as a number in either style, thousands separators
/// included ("1.234,5"): what tells a row of points from a row of names.
bool looks_numeric(std::string_view cell);
/// The decimal separator of the number cells of `rows`: a comma when some are
/// written with one (never with a comma delimiter). InputError naming the two
/// lines when the file mixes both.
Decimal detect_decimal(const std::vector<std::vector<std::string>>& rows,
                       const std::vector<std::size_t>& lines, char delimiter,
                       const std::string& source);

/// Whether `cell` reads as a unit: bracketed ("[1/s]", "(Pa)"), or a unit the
/// measured columns know or instrument exports write ("s", "°C", "Pa.s").
bool looks_like_unit(std::string_view cell);
/// "[1/s]" → "1/s"; a unit written bare is returned as it is.
std::string bare_unit(std::string_view cell);

/// A section of an export before it becomes a table.
struct Section {
  std::string title{};                           // "Flow sweep - 3", "" for a whole file
  std::vector<std::string> comments{};           // provenance: "Sample name: ..."
  std::vector<std::string> names{}, units{};     // units[c] "" when none; units may be empty
  std::vector<std::vector<std::string>> rows{};  // cells as written
  std::vector<std::size_t> lines{};              // each row's line in the file
};

/// The section as the plain CSV would hold it: column c named "name [unit]",
/// rows padded with empty cells to the header's width (spreadsheets drop
/// trailing empty cells), numbers rewritten with decimal points. InputError
/// naming the line for a row wider than the header, and for a number with
/// both separators (a thousands separator: not read, since "1.234" would be
/// ambiguous).
CsvTable section_table(const std::string& source, Section section, Decimal decimal);

}  // namespace softglass::measured
