// `rheocompass`: Anton Paar RheoCompass exports (.csv with ';' or ',', .txt
// with tabs; UTF-16 or UTF-8 with a byte-order mark, which the input gate
// converts; decimal commas in European locales). Each result of the project is
// a block:
//     Project:            <name>
//     Test:               <name>
//     Result:             <name>
//     Interval and data points:   <interval>   <points>
//     Interval data:  Point No.   Time   Shear Rate   Shear Stress ...
//                     (a row of empty cells or second names, sometimes)
//                                 [s]    [1/s]        [Pa] ...
//                     1           10     0,01         12,3 ...
// the names, units and points shifted one cell right of the keywords. Each
// interval becomes a section titled by its result (and "interval k" when the
// result has several). In an oscillation interval (one with a storage
// modulus), "Shear Strain" is the strain amplitude; rotational "Speed" in
// 1/min is the angular velocity.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

#include "common/errors.h"
#include "common/measured/export_format.h"

namespace softglass::measured {
namespace {

constexpr std::string_view kHeader = "Interval data:";

bool starts_with_keyword(std::string_view line, std::string_view keyword) {
  const auto start = line.find_first_not_of(" ");
  return start != std::string_view::npos && line.substr(start).starts_with(keyword);
}

bool recognises(const std::vector<TextLine>& lines) {
  return std::any_of(lines.begin(), lines.end(),
                     [](const TextLine& l) { return starts_with_keyword(l.text, kHeader); });
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The names of an oscillation interval in the words the columns know.
void name_oscillation_columns(std::vector<std::string>& names) {
  const bool oscillation = std::any_of(names.begin(), names.end(), [](const std::string& n) {
    return lower(n) == "storage modulus";
  });
  for (std::string& n : names) {
    if (oscillation && lower(n) == "shear strain") n = "Strain amplitude";
    if (lower(n) == "speed") n = "Angular velocity";
  }
}

bool keyword_line(std::string_view line) {
  for (std::string_view k : {"Project:", "Test:", "Result:", "Interval and data points:"})
    if (starts_with_keyword(line, k)) return true;
  return starts_with_keyword(line, kHeader);
}

MeasuredFile read(std::string_view, const std::vector<TextLine>& lines, const std::string& source) {
  const auto header = std::find_if(lines.begin(), lines.end(), [](const TextLine& l) {
    return starts_with_keyword(l.text, kHeader);
  });
  const std::string_view after = header->text.substr(header->text.find(kHeader) + kHeader.size());
  const char delimiter = after.empty() ? '\t' : after.front();
  const std::string read_as = fmt::format("{} (read as a RheoCompass export, {}-separated)", source,
                                          delimiter_name(delimiter));
  auto cells = [&](const TextLine& l) {
    return split_cells(l.text, delimiter, fmt::format("{}, line {}", source, l.number));
  };
  // Everything right of the keyword column.
  auto shifted = [](std::vector<std::string> c) {
    if (!c.empty()) c.erase(c.begin());
    return c;
  };
  std::vector<Section> sections;
  std::map<std::string, int> intervals;  // of each result
  std::string project, test, result;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::vector<std::string> c = cells(lines[i]);
    const std::string value = c.size() > 1 ? c[1] : "";
    if (c[0] == "Project:") project = value;
    if (c[0] == "Test:") test = value;
    if (c[0] == "Result:") result = value;
    if (c[0] != kHeader) continue;
    Section s{.title = result.empty() ? test : result};
    const std::pair<const char*, std::string> provenance[] = {
        {"Project", project}, {"Test", test}, {"Result", result}};
    for (const auto& [key, v] : provenance)
      if (!v.empty()) s.comments.push_back(fmt::format("{}: {}", key, v));
    s.names = shifted(c);
    ++intervals[s.title];
    s.comments.push_back(fmt::format("interval {}", intervals[s.title]));
    std::size_t j = i + 1;
    for (; j < lines.size() && !keyword_line(lines[j].text); ++j) {
      const std::vector<std::string> row = shifted(cells(lines[j]));
      const bool units = std::any_of(row.begin(), row.end(), [](const std::string& u) {
        return u.size() > 1 && u.front() == '[' && u.back() == ']';
      });
      if (units) {
        s.units = row;
        break;
      }
      if (std::any_of(row.begin(), row.end(),
                      [](const std::string& u) { return looks_numeric(u); }))
        break;  // points with no units row above them
    }
    if (s.units.empty()) {
      throw InputError(
          fmt::format("{}, line {}: interval of result '{}' has no row of bracketed "
                      "units ('[1/s]', '[Pa]') under its column names",
                      read_as, lines[i].number, s.title));
    }
    for (++j; j < lines.size() && !blank(lines[j].text) && !keyword_line(lines[j].text); ++j) {
      s.rows.push_back(shifted(cells(lines[j])));
      s.lines.push_back(lines[j].number);
    }
    name_oscillation_columns(s.names);
    sections.push_back(std::move(s));
    i = j - 1;
  }
  MeasuredFile file{.source = source, .format = "rheocompass"};
  for (Section& s : sections) {
    s.title = intervals[s.title] > 1 ? fmt::format("{} {}", s.title, s.comments.back()) : s.title;
    if (s.rows.empty()) {
      file.notes.push_back(fmt::format("'{}' left out: it has no points", s.title));
      continue;
    }
    const Decimal decimal = detect_decimal(s.rows, s.lines, delimiter, read_as);
    file.sections.push_back(section_table(source, std::move(s), decimal));
  }
  if (file.sections.empty()) throw InputError(fmt::format("{}: no interval has points", read_as));
  return file;
}

}  // namespace

FormatEntry rheocompass_format() {
  return {"rheocompass",
          "Anton Paar RheoCompass export (';', ',' or tab; decimal commas; UTF-16 or UTF-8): "
          "Result: blocks of intervals, 'Interval data:' names over a row of [units]",
          recognises, read};
}

}  // namespace softglass::measured
