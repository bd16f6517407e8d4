#include "micro/input/finished_work.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "common/errors.h"
#include "common/h5_file.h"
#include "common/parameter_input.h"

namespace softglass::micro {

namespace {

// What a stored parameter text says about the computation: the heading lines
// a tool puts before the listing (the quasi-static case's strain step), then
// every entry as "subsection/…/name = value". The listing's documentation
// comments are left out (they change with the software's wording, not with
// the computation), and so are the entries that only say where files are and
// the model preset (it only sets entries that are compared themselves).
std::vector<std::string> computation_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line) && line.starts_with("#") &&
                         line.find("Listing of Parameters") == std::string::npos;)
    out.push_back(line);
  for (const SetEntry& e : entries_set_in(text, ""))
    if (e.name != "file" && e.name != "input file" && e.key() != "model/preset")
      out.push_back(e.key() + " = " + e.value);
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
  const std::vector<std::string> was = compared(computation_of(stored)),
                                 now = compared(computation_of(expected));
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
