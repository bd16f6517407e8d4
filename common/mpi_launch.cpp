#include "common/mpi_launch.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>

namespace softglass {

namespace {

constexpr std::string_view kPrefix = "softglass-mpi-";

std::filesystem::path& own_directory() {
  static std::filesystem::path path;
  return path;
}

void remove_own_directory() {
  std::error_code ignored;
  std::filesystem::remove_all(own_directory(), ignored);
}

}  // namespace

void own_mpi_session_directory() {
  namespace fs = std::filesystem;
  if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr) return;
  std::error_code error;
  const fs::path temp = fs::temp_directory_path(error);
  if (error) return;
  for (const auto& entry : fs::directory_iterator(temp, error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(kPrefix)) continue;
    const std::string digits = name.substr(kPrefix.size());
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (::kill(static_cast<pid_t>(std::stol(digits)), 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
  own_directory() = temp / (std::string(kPrefix) + std::to_string(::getpid()));
  fs::create_directory(own_directory(), error);
  if (error) return;  // Open MPI's shared default then, as before
  setenv("OMPI_MCA_orte_tmpdir_base", own_directory().c_str(), 0);
  std::atexit(remove_own_directory);
}

}  // namespace softglass
