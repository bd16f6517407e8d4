// One sweep per output folder: an exclusive advisory lock (flock) on
// FOLDER/.sweep.lock, held for the life of the object. The kernel drops it when
// the process ends in any way, `kill -9` included, so a rerun after a crash is
// never refused by a stale lock, while a second sweep running on the same
// folder is.
#pragma once

#include <filesystem>

namespace softglass::micro {

class DirectoryLock {
 public:
  /// Creates `directory` if needed and takes the lock; InputError naming the
  /// folder if another process holds it.
  explicit DirectoryLock(const std::filesystem::path& directory);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int descriptor_ = -1;
};

}  // namespace softglass::micro
