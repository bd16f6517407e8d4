// A measured file as the instrument software exported it, cut into the
// tables the measured-curve readers take (measured_curves.h).
//
// Rheometer software writes more than a table: TA TRIOS exports a block of
// file, geometry and instrument parameters and then one `[step]` per step of
// the procedure (a name, the column names, a row of units, the points);
// Anton Paar RheoCompass writes `Result:` blocks of intervals, each with an
// `Interval data:` row of names and a row of bracketed units; spreadsheets in
// European locales write semicolons and decimal commas. Each such export
// format is one file in common/measured/ (*_format.cpp) and one line in
// registered_formats.h; `auto` takes the first, in that list's order, that
// recognises the text. Every reader returns its sections in the form the
// plain CSV has — names with their units in brackets, numbers with decimal
// points — so the layouts of columns (common/measured/layout.h) and their
// unit checks stay one for all formats.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/csv_table.h"

namespace softglass {

/// What an export records of the instrument besides its points.
struct InstrumentRecord {
  std::string geometry{};                   // its name and type as recorded, "" when none
  std::optional<double> strain_constant{};  // c_γ [1/rad]: the software's γ̇ = c_γ Ω
  std::optional<double> stress_constant{};  // c_τ [Pa/(N m)]: the software's τ = c_τ M
};

/// A measured file, read.
struct MeasuredFile {
  std::string source{};              // the file, for messages
  std::string format{};              // the export format that read it
  std::vector<CsvTable> sections{};  // a step, an interval, or the whole table
  InstrumentRecord instrument{};
  std::vector<std::string> notes{};  // what was left out, and why ("step 'Peak hold - 1': ...")
};

/// Reads `file` through the input gate (input_file.h) in the export format
/// `format` ("auto": detected). InputError naming the file, the format and the
/// cause (the line, the cell) otherwise.
MeasuredFile read_measured_file(const std::filesystem::path& file,
                                const std::string& format = "auto");
/// The same for `text` already read; `source` names it in messages.
MeasuredFile parse_measured_file(std::string_view text, const std::string& source,
                                 const std::string& format = "auto");

/// "auto" and the name of every export format, for --format's allowed values.
std::vector<std::string> measured_file_formats();

}  // namespace softglass
