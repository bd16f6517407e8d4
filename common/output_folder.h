// The folder a command writes its result into, made ready before any work.
//
// `macro run` and `macro compare` (their result folder), `bridge
// amplitude-sweep` (-o DIR) and `micro slip` (the walls' output directory)
// write into a folder they create if it is missing. Whether they can is known
// before the work: a path naming a file, a folder that cannot be created or
// one that cannot be written is refused with one line naming the path and the
// reason (InputError, exit code 2), instead of a raw filesystem error after
// the computation. A folder made here and still empty when the object goes
// (the command refused its input or failed) is removed again, so that a
// command that wrote nothing leaves no folder behind.
#pragma once

#include <filesystem>
#include <vector>

namespace softglass {

class OutputFolder {
 public:
  /// Creates `path` and its missing parents; InputError "output folder 'P'
  /// is a file, not a folder", "... cannot be created: REASON" or "... is
  /// not writable: REASON" otherwise.
  explicit OutputFolder(std::filesystem::path path);
  /// Removes the folders the constructor made, innermost first, as far as
  /// they are empty (a folder holding anything is kept).
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  void remove_created();

  std::filesystem::path path_;
  std::vector<std::filesystem::path> created_;  // outermost first
};

}  // namespace softglass
