// The memory check before work: what the machine gives is positive and no
// more than its physical memory, and a request beyond it is refused naming both.
#include <gtest/gtest.h>
#include <unistd.h>

#include "common/errors.h"
#include "common/memory_budget.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {

TEST(MemoryBudget, RefusesWhatTheMachineCannotGive) {
  const double physical = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  const double available = static_cast<double>(memory_available());
  EXPECT_GT(available, 0.0);
  EXPECT_LE(available, physical);
  EXPECT_NO_THROW(require_memory(0.5 * available, "half of it"));
  try {
    require_memory(2.0 * physical, "a packing of N = 5e7 particles");
    ADD_FAILURE() << "twice the physical memory was accepted";
  } catch (const InputError& e) {
    testing::expect_contains(e.what(), {"a packing of N = 5e7 particles needs at least",
                                        "GB of memory; this machine gives a process"});
  }
}

}  // namespace
}  // namespace softglass
