#include "micro/app/finished_work.h"

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <sstream>
#include <vector>

#include "common/errors.h"
#include "common/h5_file.h"

namespace softglass::micro {

namespace {

// The entries of a printed parameter text as "subsection/…/name = value", in
// order. The documentation comments of the listing are dropped (they change
// with the software's wording, not with the computation); the heading lines a
// tool puts before the listing (the quasi-static case's strain step) are kept.
std::vector<std::string> entries_of(const std::string& text) {
  static const std::regex subsection(R"(^\s*subsection\s+(.*\S)\s*$)");
  static const std::regex end(R"(^\s*end\s*$)");
  static const std::regex set(R"(^\s*set\s+([^=]*\S)\s*=\s*([^#]*?)\s*(#.*)?$)");
  std::vector<std::string> path, out;
  bool listing = false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      listing = listing || line.find("Listing of Parameters") != std::string::npos;
      if (!listing) out.push_back(line);
    } else if (std::regex_match(line, m, subsection)) {
      path.push_back(m[1].str());
    } else if (std::regex_match(line, end)) {
      if (!path.empty()) path.pop_back();
    } else if (std::regex_match(line, m, set)) {
      if (m[1] == "file" || m[1] == "input file") continue;  // where, not what
      std::string key;
      for (const std::string& s : path) key += s + "/";
      out.push_back(key + m[1].str() + " = " + m[2].str());
    }
  }
  return out;
}

}  // namespace

void require_same_computation(const std::filesystem::path& file, const std::string& expected,
                              const std::vector<std::string>& subsections) {
  std::string stored;
  try {
    stored = H5File::open(file).root().read_string("parameters");
  } catch (const std::exception& e) {
    throw InputError(fmt::format("'{}' is not a finished packing or run of micro ({}); move it "
                                 "away to recompute it",
                                 file.string(), e.what()));
  }
  const auto compared = [&](std::vector<std::string> entries) {
    if (subsections.empty()) return entries;
    std::erase_if(entries, [&](const std::string& e) {
      return std::none_of(subsections.begin(), subsections.end(),
                          [&](const std::string& s) { return e.starts_with(s + "/"); });
    });
    return entries;
  };
  const std::vector<std::string> was = compared(entries_of(stored)),
                                 now = compared(entries_of(expected));
  for (std::size_t k = 0; k < std::max(was.size(), now.size()); ++k) {
    const std::string a = k < was.size() ? was[k] : "(nothing)";
    const std::string b = k < now.size() ? now[k] : "(nothing)";
    if (a == b) continue;
    throw InputError(fmt::format(
        "'{}' is a finished result of another computation: it was made with '{}', the sweep "
        "file now gives '{}'. A sweep reuses only what it would compute again; give a new "
        "output directory, or remove the old results to recompute them",
        file.string(), a, b));
  }
}

}  // namespace softglass::micro
