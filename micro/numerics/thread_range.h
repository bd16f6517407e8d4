// The share of `count` items that thread t of `threads` works on: contiguous
// ranges of ceil(count / threads), the last one shorter. Used where a loop is
// split by hand (outside `omp for`), so that every such split is the same.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>

namespace softglass::micro {

inline std::pair<std::size_t, std::size_t> thread_range(std::size_t count, std::size_t threads,
                                                        std::size_t t) {
  const std::size_t chunk = (count + threads - 1) / threads;
  return {std::min(count, t * chunk), std::min(count, (t + 1) * chunk)};
}

}  // namespace softglass::micro
