#include "common/atomic_output.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "common/errors.h"

namespace softglass {

namespace {

const std::string kTemporarySuffix = ".tmp";

std::filesystem::path directory_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

}  // namespace

void remove_dead_temporaries(const std::filesystem::path& directory, const std::string& name) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    const std::string file = entry.path().filename().string();
    const auto suffix = file.rfind(kTemporarySuffix);
    if (suffix == std::string::npos || suffix == 0) continue;
    if (!name.empty() && file.compare(0, suffix, name) != 0) continue;
    const std::string digits = file.substr(suffix + kTemporarySuffix.size());
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      std::filesystem::remove(entry.path(), ignored);
    }
  }
}

void write_file(const std::filesystem::path& path, const std::string& shown,
                     const std::function<void(std::ostream&)>& body) {
  errno = 0;
  std::ofstream file(path, std::ios::binary);
  if (file) body(file);
  file.close();
  if (!file) {
    throw NumericalError(fmt::format("cannot write '{}': {}", shown,
                                     errno != 0 ? std::strerror(errno) : "write error"));
  }
}

void AtomicOutput::write_and_commit(const std::function<void(std::ostream&)>& body) {
  write_file(temporary_, final_.string(), body);
  commit();
}

AtomicOutput::AtomicOutput(std::filesystem::path final_path, bool overwrite)
    : final_(std::move(final_path)) {
  if (final_.empty()) throw InputError("output path is empty");
  if (std::filesystem::exists(final_) && !overwrite) {
    throw OutputExistsError("output file '" + final_.string() +
                            "' exists; pass --force to overwrite it");
  }
  const auto dir = directory_of(final_);
  if (!std::filesystem::is_directory(dir)) {
    throw InputError("output directory '" + dir.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(final_)) {
    throw InputError("output '" + final_.string() + "' is a directory; name a file to write");
  }
  temporary_ = final_;
  temporary_ += kTemporarySuffix + std::to_string(::getpid());
  // The temporary file is claimed now, so that an output that cannot be
  // written (a read-only folder, a full quota) is refused before the work, not
  // after it.
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (fd < 0) {
    throw InputError(fmt::format("cannot write in output directory '{}': {}", dir.string(),
                                 std::strerror(errno)));
  }
  ::close(fd);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicOutput::commit(bool tidy) {
  std::error_code error;
  std::filesystem::rename(temporary_, final_, error);
  if (error) {
    throw NumericalError(fmt::format("cannot put the finished '{}' in place of '{}': {}",
                                     temporary_.string(), final_.string(), error.message()));
  }
  committed_ = true;
  if (tidy) remove_dead_temporaries(directory_of(final_), final_.filename().string());
}

}  // namespace softglass
