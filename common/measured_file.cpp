#include "common/measured_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/errors.h"
#include "common/input_file.h"
#include "common/measured/export_format.h"
#include "common/measured/registered_formats.h"

namespace softglass {

namespace measured {

#define SOFTGLASS_DECLARE_FORMAT(name) FormatEntry name##_format();
SOFTGLASS_MEASURED_FORMATS(SOFTGLASS_DECLARE_FORMAT)
#undef SOFTGLASS_DECLARE_FORMAT

const Registry<FormatEntry>& formats() {
#define SOFTGLASS_LIST_FORMAT(name) name##_format(),
  static const Registry<FormatEntry> registry("measured-file format",
                                              {SOFTGLASS_MEASURED_FORMATS(SOFTGLASS_LIST_FORMAT)});
#undef SOFTGLASS_LIST_FORMAT
  return registry;
}

}  // namespace measured

MeasuredFile parse_measured_file(std::string_view text, const std::string& source,
                                 const std::string& format) {
  const std::vector<measured::TextLine> lines = measured::lines_of(text);
  const measured::FormatEntry* detected = nullptr;
  for (const measured::FormatEntry& f : measured::formats().entries())
    if (!detected && f.recognises(lines)) detected = &f;
  if (format == "auto") return detected->read(text, lines, source);
  const measured::FormatEntry& chosen = measured::formats().at(format);
  if (!chosen.recognises(lines)) {
    throw InputError(
        fmt::format("{}: --format {} reads {}; this file is not one: it looks like "
                    "{} ({}), which --format auto reads",
                    source, chosen.name, chosen.summary, detected->name, detected->summary));
  }
  return chosen.read(text, lines, source);
}

MeasuredFile read_measured_file(const std::filesystem::path& file, const std::string& format) {
  return parse_measured_file(read_input_text(file, "measured file"), file.string(), format);
}

std::vector<std::string> measured_file_formats() {
  std::vector<std::string> names{"auto"};
  for (const std::string& n : measured::formats().names()) names.push_back(n);
  return names;
}

}  // namespace softglass
