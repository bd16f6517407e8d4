// A strict reader of comma-separated tables: the form of every bridge input
// and of the measured files `macro compare` reads.
//
// Lines starting with `#` are comments (the ones before the first row are
// kept: they carry provenance); blank lines are skipped. The first other line
// is the header; every later line is a row with as many cells as the header.
// A comment "# units: u1,u2,..." right under the header (the form the tools
// write, csv_writer.h) gives each column its unit, read as if the header said
// "name [unit]".
// Double-quoted cells may hold commas ("" is a quote). Cells are trimmed.
// A number is read whole (no trailing text) and must be finite: an empty cell,
// `nan` or `inf` is refused with the file, line and column named.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace softglass {

class CsvTable {
 public:
  /// Reads `file`; InputError when it cannot be read or is malformed.
  static CsvTable read(const std::filesystem::path& file);
  /// Parses `text`; `source` names it in messages (usually the file name).
  static CsvTable parse(std::string_view text, std::string source);
  /// A table assembled by a reader of another text form (an instrument
  /// export's section): `lines[r]` is row r's line in the file, for messages;
  /// `title` names the section (a step of the export), "" for a whole file.
  static CsvTable from_rows(std::string source, std::string title,
                            std::vector<std::string> comments, std::vector<std::string> header,
                            std::vector<std::vector<std::string>> rows,
                            std::vector<std::size_t> lines);

  /// The section's name in its file ("Flow sweep - 3"), "" when the table is the whole file.
  const std::string& title() const { return title_; }

  const std::string& source() const { return source_; }
  const std::vector<std::string>& comments() const { return comments_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return cells_.size(); }
  std::size_t columns() const { return header_.size(); }
  /// Line number of a row in the file (1-based), for messages.
  std::size_t line(std::size_t row) const { return lines_[row]; }

  const std::string& text(std::size_t row, std::size_t column) const { return cells_[row][column]; }
  /// The cell as a finite number; InputError naming source, line and column otherwise.
  double number(std::size_t row, std::size_t column) const;
  /// "file, line 7, column 'sigma [E*]'": the place of a cell in messages.
  std::string where(std::size_t row, std::size_t column) const;

  /// Index of the column whose header is exactly `name`.
  std::optional<std::size_t> find(std::string_view name) const;

 private:
  /// The units line's units attached to the header's names.
  void attach_units(std::string_view units, std::size_t line);

  std::string source_, title_;
  std::vector<std::string> comments_, header_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<std::size_t> lines_;
};

/// A column header split into its name and units: "sigma [E*]" → {"sigma", "E*"}.
/// Without brackets the units are empty.
struct ColumnName {
  std::string name, units;
};
ColumnName split_units(std::string_view header);

/// One line split at `delimiter` into trimmed cells; double quotes protect
/// delimiters ("" inside quotes is a quote). InputError naming `where` for an
/// unterminated quote.
std::vector<std::string> split_cells(std::string_view line, char delimiter,
                                     const std::string& where);

}  // namespace softglass
