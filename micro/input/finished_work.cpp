#include "micro/input/finished_work.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <utility>
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

// The first entry in which the parameter texts `stored` and `expected`
// differ, as (stored, expected); only the entries of `subsections` when given.
std::optional<std::pair<std::string, std::string>> first_difference(
    const std::string& stored, const std::string& expected,
    const std::vector<std::string>& subsections = {}) {
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
    std::string a = k < was.size() ? was[k] : "(nothing)";
    std::string b = k < now.size() ? now[k] : "(nothing)";
    if (a != b) return std::pair{std::move(a), std::move(b)};
  }
  return std::nullopt;
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
  if (const auto d = first_difference(stored, expected, subsections))
    throw InputError(fmt::format(
        "'{}' is a finished result of another computation: it was made with '{}', the sweep "
        "file now gives '{}'. A sweep reuses only what it would compute again; give a new "
        "output directory, or remove the old results to recompute them",
        file.string(), d->first, d->second));
}

void require_checkpoint_of_same_computation(const std::filesystem::path& file,
                                            const std::string& expected) {
  const H5File checkpoint = H5File::open(file);
  if (!checkpoint.root().has_child("parameters")) return;
  if (const auto d = first_difference(checkpoint.root().read_string("parameters"), expected))
    throw InputError(fmt::format(
        "'{}' is the checkpoint of another computation: its run was made with '{}', this run "
        "gives '{}'; restore that entry to go on from it",
        file.string(), d->first, d->second));
}

}  // namespace softglass::micro
