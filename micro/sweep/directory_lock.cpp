#include "micro/sweep/directory_lock.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "common/errors.h"

namespace softglass::micro {

DirectoryLock::DirectoryLock(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw InputError(fmt::format("cannot create the output folder '{}': {}", directory.string(),
                                 error.message()));
  const std::string file = (directory / ".sweep.lock").string();
  descriptor_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor_ < 0)
    throw InputError(fmt::format("cannot open the lock file '{}': {}", file, std::strerror(errno)));
  if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
    const int reason = errno;
    ::close(descriptor_);
    descriptor_ = -1;
    if (reason == EWOULDBLOCK)
      throw InputError(fmt::format(
          "another sweep is running on '{}' (it holds {}); wait for it or choose another "
          "output directory",
          directory.string(), file));
    throw InputError(fmt::format("cannot lock '{}': {}", file, std::strerror(reason)));
  }
}

DirectoryLock::~DirectoryLock() {
  if (descriptor_ >= 0) ::close(descriptor_);  // releases the lock
}

}  // namespace softglass::micro
