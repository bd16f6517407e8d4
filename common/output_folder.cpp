#include "common/output_folder.h"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "common/errors.h"

namespace softglass {

namespace {

std::string what_it_is(const std::filesystem::path& path) {
  std::error_code ignored;
  return std::filesystem::is_regular_file(path, ignored) ? "is a file, not a folder"
                                                         : "is not a folder";
}

}  // namespace

OutputFolder::OutputFolder(std::filesystem::path path) : path_(std::move(path)) {
  if (path_.empty()) throw InputError("the output folder's path is empty");
  // "out/" names the folder "out".
  std::filesystem::path folder = path_;
  while (!folder.has_filename() && folder.has_relative_path()) folder = folder.parent_path();
  std::error_code error;
  if (std::filesystem::exists(folder, error)) {
    if (!std::filesystem::is_directory(folder, error))
      throw InputError(fmt::format("output folder '{}' {}", path_.string(), what_it_is(folder)));
  } else {
    // The missing folders, innermost first, up to the nearest that exists.
    std::vector<std::filesystem::path> missing;
    std::filesystem::path existing = folder;
    for (; !existing.empty() && !std::filesystem::exists(existing, error);
         existing = existing.parent_path()) {
      missing.push_back(existing);
      if (existing == existing.parent_path()) break;
    }
    if (!existing.empty() && std::filesystem::exists(existing, error) &&
        !std::filesystem::is_directory(existing, error)) {
      throw InputError(fmt::format("output folder '{}' cannot be created: '{}' {}", path_.string(),
                                   existing.string(), what_it_is(existing)));
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (::mkdir(it->c_str(), 0777) == 0) {
        created_.push_back(*it);
        continue;
      }
      const int reason = errno;
      // Another process may have made it meanwhile: then it is used as it is.
      if (reason == EEXIST && std::filesystem::is_directory(*it, error)) continue;
      remove_created();
      throw InputError(fmt::format("output folder '{}' cannot be created: {}", path_.string(),
                                   std::strerror(reason)));
    }
  }
  // Root passes this test on any folder of a writable file system; the
  // temporaries claimed next (atomic_output.h) find out the rest.
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    const int reason = errno;
    remove_created();
    throw InputError(fmt::format("output folder '{}' is not writable: {}", path_.string(),
                                 std::strerror(reason)));
  }
}

OutputFolder::~OutputFolder() {
  remove_created();
}

void OutputFolder::remove_created() {
  // rmdir() removes only an empty folder: whatever a command wrote stays.
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) ::rmdir(it->c_str());
  created_.clear();
}

}  // namespace softglass
