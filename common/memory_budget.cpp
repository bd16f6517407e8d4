#include "common/memory_budget.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "common/errors.h"

namespace softglass {

std::uintmax_t memory_available() {
  std::uintmax_t bytes = static_cast<std::uintmax_t>(sysconf(_SC_PHYS_PAGES)) *
                         static_cast<std::uintmax_t>(sysconf(_SC_PAGE_SIZE));
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = std::min<std::uintmax_t>(bytes, limit.rlim_cur);
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  std::string word;
  if (cgroup >> word && word != "max") {
    try {
      bytes = std::min<std::uintmax_t>(bytes, std::stoull(word));
    } catch (const std::exception&) {
      // Not a number: no limit to apply.
    }
  }
  return bytes;
}

void require_memory(double bytes, const std::string& what) {
  const double available = static_cast<double>(memory_available());
  if (bytes <= available) return;
  throw InputError(fmt::format("{} needs at least {:.3g} GB of memory; this machine gives a process "
                               "{:.3g} GB (physical memory, ulimit -v, control group): use fewer "
                               "particles or a larger machine",
                               what, bytes / 1e9, available / 1e9));
}

}  // namespace softglass
