// Memory a computation will need, checked against what this machine can give
// before any work: a request far beyond it should be refused with both figures
// named, not end in std::bad_alloc (or the kernel's OOM killer) minutes later.
#pragma once

#include <cstdint>
#include <string>

namespace softglass {

/// The bytes this process may use: the smallest of the physical memory, the
/// address-space limit (ulimit -v) and the control group's memory.max.
std::uintmax_t memory_available();

/// InputError naming `what`, the estimate and the memory available when
/// `bytes`, a lower bound of what the work needs, exceeds the latter.
void require_memory(double bytes, const std::string& what);

}  // namespace softglass
