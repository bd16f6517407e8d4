#include "macro/app/result_folder.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "common/errors.h"
#include "macro/app/mpi_gather.h"

namespace softglass::macro::app {

namespace {

// A name a manifest may list: a file of the folder itself, never a path out
// of it (a manifest is a file anyone could have edited).
bool plain_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name != kManifest &&
         std::filesystem::path(name).filename() == name;
}

// The files of the folder's previous result: its manifest's list, or, in a
// folder written before manifests, its field files.
std::set<std::string> previous_result(const std::filesystem::path& directory) {
  std::set<std::string> names;
  std::ifstream manifest(directory / kManifest);
  if (manifest) {
    for (std::string line; std::getline(manifest, line);)
      if (!line.starts_with('#') && plain_name(line)) names.insert(line);
    return names;
  }
  static const std::regex field_file(R"(solution_\d+\.vtu)");
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(name, field_file)) names.insert(name);
  }
  return names;
}

// "name\ttemporary" lines, to hand rank 0's temporaries to every rank.
std::string listing(const std::map<std::string, std::unique_ptr<AtomicOutput>>& files) {
  std::string text;
  for (const auto& [name, file] : files) text += name + "\t" + file->temporary_path().string() + "\n";
  return text;
}

}  // namespace

ResultFolder::ResultFolder(std::filesystem::path directory, const std::vector<std::string>& names,
                           bool force)
    : directory_(std::move(directory)), force_(force) {
  const MPI_Comm world = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(world) == 0;
  // Whatever stops rank 0 here (an existing result, a folder it cannot write,
  // a file where the folder should be) must stop the other ranks too, or they
  // would wait for it for ever.
  std::exception_ptr failure;
  if (root) {
    try {
      folder_.emplace(directory_);
      for (const std::string& name : names)
        files_[name] = std::make_unique<AtomicOutput>(directory_ / name, force);
      files_[kManifest] = std::make_unique<AtomicOutput>(directory_ / kManifest, force);
    } catch (const std::exception&) {
      failure = std::current_exception();
      files_.clear();
      folder_.reset();
    }
  }
  if (broadcast_flag(world, failure != nullptr)) {
    if (root) std::rethrow_exception(failure);
    refused_ = true;
    return;
  }
  std::istringstream lines(broadcast_text(world, listing(files_)));
  for (std::string name, temporary; std::getline(lines, name, '\t') && std::getline(lines, temporary);)
    temporaries_[name] = temporary;
}

const std::string& ResultFolder::temporary(const std::string& name) const {
  return temporaries_.at(name);
}

void ResultFolder::discard(const std::string& name) {
  files_.erase(name);
  discarded_.insert(name);
}

void ResultFolder::commit() {
  std::set<std::string> previous = previous_result(directory_);
  previous.insert(discarded_.begin(), discarded_.end());
  std::unique_ptr<AtomicOutput> manifest = std::move(files_.at(kManifest));
  files_.erase(kManifest);
  write_file(manifest->temporary_path(), manifest->final_path().string(), [&](std::ostream& out) {
    out << "# softglass macro: the files of one result, listed when all were in place "
           "(docs/macro.md)\n";
    for (const auto& [name, file] : files_) out << name << "\n";
  });
  {
    // A signal in between would leave the new files beside the old ones.
    const TerminatingSignalsHeld held;
    const auto remove_previous = [&] {
      for (const std::string& name : previous) {
        if (files_.contains(name)) continue;
        std::error_code ignored;  // already gone: nothing to remove
        std::filesystem::remove(directory_ / name, ignored);
      }
    };
    if (force_) {
      for (const auto& [name, file] : files_) file->commit(/*tidy=*/false);  // tidied once below
      remove_previous();
      manifest->commit(/*tidy=*/false);
    } else {
      // Every file and the manifest are put in place without replacing any,
      // or none is (a concurrent run's result is there); only then is the
      // previous result's remainder removed.
      std::vector<AtomicOutput*> set;
      for (const auto& [name, file] : files_) set.push_back(file.get());
      set.push_back(manifest.get());
      try {
        AtomicOutput::commit_together(set, /*tidy=*/false);
      } catch (const OutputExistsError&) {
        throw OutputExistsError(fmt::format(
            "another process put its result in '{}' while this one ran: that result is kept and "
            "this one's discarded (pass --force to replace it)",
            directory_.string()));
      }
      remove_previous();
    }
  }
  remove_dead_temporaries(directory_);
}

}  // namespace softglass::macro::app
