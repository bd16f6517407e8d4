// An export format of measured files (measured_file.h): how an instrument's
// software lays out its text. Each format is one file that defines its
// registry entry and one line in registered_formats.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/measured/export_text.h"
#include "common/measured_file.h"
#include "common/registry.h"

namespace softglass::measured {

/// A format: its name and summary, the test that recognises its text, and its
/// reader, which returns the file's sections in the plain CSV's form
/// (export_text.h, section_table) or throws InputError naming the line.
struct FormatEntry {
  std::string name;
  std::string summary;
  bool (*recognises)(const std::vector<TextLine>& lines) = nullptr;
  MeasuredFile (*read)(std::string_view text, const std::vector<TextLine>& lines,
                       const std::string& source) = nullptr;
};

/// Every format, in the order `auto` tries them.
const Registry<FormatEntry>& formats();

}  // namespace softglass::measured
