// The output folder of one `macro run` or `macro compare`: every file of the
// result goes through an AtomicOutput (common/atomic_output.h), and the folder
// holds one result's files.
//
// Every file is claimed before any work (so that an existing result is refused
// at once, exit code 3 without --force) and written under its temporary name —
// the tables by rank 0, the field files by whichever ranks solve their points.
// Nothing takes its final name until the whole result is written: commit()
// renames them all, then removes the files of the folder's previous result
// that this one does not have (a forced run with fewer field files, a
// comparison without its plot), and writes `manifest.txt`, the list of the
// result's files, last. The previous result's files are those its manifest
// lists (a folder written before manifests: its solution_NNN.vtu files).
// Files the folder holds besides are not touched. A run that fails leaves the
// previous result as it was and no temporary file (and no folder, when it
// made the folder: common/output_folder.h).
//
// Without --force nothing is replaced at the commit either: when another
// process put a result in the folder while this one ran (two runs started
// together), the commit takes back the files it had put in place and fails
// with OutputExistsError (exit code 3), and the other result stays whole.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/atomic_output.h"
#include "common/output_folder.h"

namespace softglass::macro::app {

inline constexpr const char* kManifest = "manifest.txt";

class ResultFolder {
 public:
  /// Collective over MPI_COMM_WORLD. Rank 0 creates `directory` and claims
  /// `names` and the manifest: OutputExistsError on rank 0 when one exists and
  /// `force` is false (InputError when the folder is a file, cannot be created
  /// or cannot be written); the other ranks then see refused().
  ResultFolder(std::filesystem::path directory, const std::vector<std::string>& names, bool force);

  /// On ranks other than 0, after rank 0 could not claim the folder: stop.
  bool refused() const { return refused_; }
  /// The same on every rank: where the file `name` is to be written.
  const std::string& temporary(const std::string& name) const;
  std::filesystem::path path(const std::string& name) const { return directory_ / name; }
  /// Rank 0: the file `name` turned out not to be part of the result (a plot
  /// that could not be made); its temporary is removed, an older one too.
  void discard(const std::string& name);
  /// Rank 0, once every file is written: the result takes the folder's place
  /// (OutputExistsError without `force` when another process's did meanwhile).
  void commit();

 private:
  std::filesystem::path directory_;
  bool force_;
  std::optional<OutputFolder> folder_;  // rank 0; outlives the files' temporaries
  std::map<std::string, std::unique_ptr<AtomicOutput>> files_;  // rank 0
  std::map<std::string, std::string> temporaries_;
  std::set<std::string> discarded_;  // rank 0
  bool refused_ = false;
};

}  // namespace softglass::macro::app
