// `trios`: TA Instruments TRIOS exports, as text (tab-separated) or CSV, in
// both of TRIOS's layouts:
//   - "Export to text/CSV": "Key<TAB>Value" lines and bracketed blocks of
//     file, geometry and instrument parameters, then one block per step of
//     the procedure: "[step]", the step's name ("Flow sweep - 3"), the column
//     names, a row of units (bare: "Pa", "1/s", "µN.m"), the points, a blank
//     line;
//   - "Export to LIMS": the same blocks with "Step name<TAB>...", "Number of
//     points<TAB>N", "Variables<TAB>names...", a row of units under the names,
//     and each point as "Data point<TAB>values...".
// Steps are kept by their kind, read from their name: steady flow ("Flow
// sweep", "Steady state flow", "Flow curve") and amplitude sweeps ("Amplitude
// sweep", "Oscillation amplitude"). Transients (peak holds, time sweeps,
// ramps, creep, relaxation) hold stresses and rates too, but are not flow
// curves: they are left out and named in the file's notes. The geometry's
// name and type, and its stress and strain constants ("Stress constant
// 79577.5 Pa/N.m", "Strain constant 20.0 1/rad"), are read into the
// instrument record: `macro compare` converts with them.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

#include "common/errors.h"
#include "common/measured/export_format.h"

namespace softglass::measured {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// "[step]" alone on its line (delimiters aside).
bool is_step_marker(std::string_view line) {
  const auto start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos) return false;
  line.remove_prefix(start);
  return lower(line.substr(0, 6)) == "[step]" && blank(line.substr(6));
}

bool recognises(const std::vector<TextLine>& lines) {
  return std::any_of(lines.begin(), lines.end(),
                     [](const TextLine& l) { return is_step_marker(l.text); });
}

// "Flow sweep - 3", "Flow sweep (25.0 °C)" → "flow sweep".
std::string step_kind(const std::string& name) {
  std::string kind = lower(name);
  if (const auto paren = kind.find('('); paren != std::string::npos) kind.resize(paren);
  if (const auto dash = kind.rfind(" - "); dash != std::string::npos) kind.resize(dash);
  while (!kind.empty() && kind.back() == ' ') kind.pop_back();
  return kind;
}

bool kept(const std::string& kind) {
  for (const char* k : {"flow sweep", "steady state flow", "flow curve", "amplitude sweep",
                        "oscillation amplitude"})
    if (kind == k) return true;
  return false;
}

// "79577.5 Pa/N.m" → 79577.5 when its unit is one of `units` (spaces, '·' and
// parentheses aside); nullopt otherwise.
std::optional<double> constant(const std::string& text, std::initializer_list<const char*> units) {
  const auto space = text.find(' ');
  if (space == std::string::npos) return std::nullopt;
  std::string number = text.substr(0, space), unit;
  std::replace(number.begin(), number.end(), ',', '.');
  const std::string written = text.substr(space + 1);
  for (std::size_t k = 0; k < written.size(); ++k) {
    if (written.compare(k, 2, "·") == 0) {  // a middle dot, two bytes in UTF-8
      unit += '.';
      ++k;
    } else if (written[k] != ' ' && written[k] != '(' && written[k] != ')') {
      unit += written[k];
    }
  }
  if (std::none_of(units.begin(), units.end(), [&](const char* u) { return unit == u; }))
    return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error != std::errc() || end != number.data() + number.size() || !(value > 0))
    return std::nullopt;
  return value;
}

struct Reader {
  const std::vector<TextLine>& lines;
  const std::string& source;
  char delimiter;

  std::vector<std::string> cells(const TextLine& l) const {
    return split_cells(l.text, delimiter, fmt::format("{}, line {}", source, l.number));
  }
  std::string where(std::size_t i) const {
    return fmt::format("{} (read as a TRIOS export), line {}", source, lines[i].number);
  }

  // The parameters above the first step: comments, geometry and constants.
  std::size_t header(MeasuredFile& file, std::vector<std::string>& comments) const {
    std::string block, geometry_name, geometry_type;
    std::size_t i = 0;
    for (; i < lines.size() && !is_step_marker(lines[i].text); ++i) {
      if (blank(lines[i].text)) continue;
      const std::vector<std::string> c = cells(lines[i]);
      if (c[0].starts_with('[')) {
        block = lower(c[0]);
        continue;
      }
      const std::string key = lower(c[0]), value = c.size() > 1 ? c[1] : "";
      if (block.empty() && !key.empty() && !value.empty()) comments.push_back(c[0] + ": " + value);
      if (block == "[geometry parameters]" && key == "name") geometry_name = value;
      if (block == "[geometry parameters]" && key == "geometry type") geometry_type = value;
      if (key == "geometry name" && geometry_name.empty()) geometry_name = value;
      if (key == "stress constant") {
        file.instrument.stress_constant = constant(value, {"Pa/N.m", "Pa/Nm"});
        if (!file.instrument.stress_constant)
          file.notes.push_back(
              fmt::format("{}: stress constant '{}' not read (expected Pa/N.m)", where(i), value));
      }
      if (key == "strain constant") {
        file.instrument.strain_constant = constant(value, {"1/rad", "rad^-1"});
        if (!file.instrument.strain_constant)
          file.notes.push_back(
              fmt::format("{}: strain constant '{}' not read (expected 1/rad)", where(i), value));
      }
    }
    file.instrument.geometry = geometry_type.empty() || geometry_name.empty()
                                   ? geometry_name + geometry_type
                                   : fmt::format("{} ({})", geometry_name, geometry_type);
    return i;
  }

  // The step whose "[step]" line is `i`; returns the line after it.
  std::size_t step(std::size_t i, MeasuredFile& file, const std::vector<std::string>& comments,
                   std::vector<Section>& sections) const {
    const std::size_t marker = i++;
    auto next = [&] {
      while (i < lines.size() && blank(lines[i].text)) ++i;
      return i < lines.size() && !is_step_marker(lines[i].text);
    };
    if (!next()) throw InputError(where(marker) + ": a [step] without a name or points");
    std::vector<std::string> c = cells(lines[i]);
    const bool lims = lower(c[0]) == "step name";
    Section s{.title = lims && c.size() > 1 ? c[1] : c[0], .comments = comments};
    ++i;
    if (lims && next() && lower(cells(lines[i])[0]) == "number of points") ++i;
    if (!next())
      throw InputError(fmt::format("{}: step '{}' has no column names", where(marker), s.title));
    const std::size_t names_line = i;
    s.names = cells(lines[i++]);
    if (lims && !s.names.empty() && lower(s.names[0]) == "variables")
      s.names.erase(s.names.begin());
    if (i >= lines.size() || blank(lines[i].text) || is_step_marker(lines[i].text))
      throw InputError(fmt::format("{}: step '{}' has column names but no row of units under them",
                                   where(names_line), s.title));
    s.units = cells(lines[i]);
    if (lims && s.units.size() == s.names.size() + 1 && s.units[0].empty())
      s.units.erase(s.units.begin());
    for (const std::string& unit : s.units)
      if (looks_numeric(unit))
        throw InputError(fmt::format(
            "{}: step '{}': the row under the column names should hold their units, but holds "
            "the number '{}'",
            where(i), s.title, unit));
    for (++i; i < lines.size() && !blank(lines[i].text) && !is_step_marker(lines[i].text); ++i) {
      std::vector<std::string> row = cells(lines[i]);
      if (lims && !row.empty() && lower(row[0]) == "data point") row.erase(row.begin());
      s.rows.push_back(std::move(row));
      s.lines.push_back(lines[i].number);
    }
    // TRIOS's "Velocity" of a rotational step is the geometry's angular velocity.
    for (std::size_t k = 0; k < s.names.size() && k < s.units.size(); ++k)
      if (lower(s.names[k]) == "velocity" && (s.units[k] == "rad/s" || s.units[k] == "rpm"))
        s.names[k] = "Angular velocity";
    const std::string kind = step_kind(s.title);
    if (!kept(kind)) {
      file.notes.push_back(
          fmt::format("step '{}' left out: a {} is not a steady flow curve or an amplitude sweep",
                      s.title, kind.empty() ? "step without a name" : kind));
    } else if (s.rows.empty()) {
      file.notes.push_back(fmt::format("step '{}' left out: it has no points", s.title));
    } else {
      sections.push_back(std::move(s));
    }
    return i;
  }
};

MeasuredFile read(std::string_view, const std::vector<TextLine>& lines, const std::string& source) {
  const bool tabs = std::any_of(lines.begin(), lines.end(), [](const TextLine& l) {
    return l.text.find('\t') != std::string_view::npos;
  });
  const Reader reader{lines, source, tabs ? '\t' : ','};
  MeasuredFile file{.source = source, .format = "trios"};
  std::vector<std::string> comments;
  std::vector<Section> sections;
  for (std::size_t i = reader.header(file, comments); i < lines.size();) {
    if (is_step_marker(lines[i].text)) {
      i = reader.step(i, file, comments, sections);
    } else {
      ++i;
    }
  }
  if (sections.empty()) {
    throw InputError(fmt::format(
        "{} (read as a TRIOS export): no step is a steady flow curve or an amplitude sweep ({})",
        source, fmt::join(file.notes, "; ")));
  }
  for (Section& s : sections) {
    const Decimal decimal = detect_decimal(s.rows, s.lines, reader.delimiter, source);
    file.sections.push_back(section_table(source, std::move(s), decimal));
  }
  return file;
}

}  // namespace

FormatEntry trios_format() {
  return {"trios",
          "TA Instruments TRIOS text, CSV or LIMS export: parameter blocks, then [step] blocks "
          "(name, column names, units row, points); steady flow and amplitude-sweep steps are read",
          recognises, read};
}

}  // namespace softglass::measured
