// Uncertainties of everything fit_sweep estimates, from the scatter between
// packings: the sweep is redrawn (sweep/resampling.h) and refitted many times,
// and the standard deviation of each number over the replicates is its
// standard error.
//
// Replicate b draws from its own generator, seeded by (seed, b), so results do
// not depend on the number of threads. A replicate whose fit fails leaves NaN
// in the numbers concerned; their standard deviations use the finite values and
// the failure counts are reported, since replicates that fail are not a random
// subset and a high failure rate makes the error itself unreliable.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bridge/sweep/resampling.h"
#include "bridge/sweep/sweep_fit.h"

namespace softglass::bridge {

struct BootstrapOptions {
  std::size_t replicates = 1000;
  std::uint64_t seed = 1;
};

struct BootstrapResult {
  std::size_t replicates = 0;
  SweepFit error;  // standard deviation over the replicates, same layout as the estimate
  /// Per group and quantity: the correlation of ln|consistency| and the exponent
  /// over the replicates (needed to propagate errors into K = E* k (η_s/E*)^m).
  std::vector<PerQuantity<double>> log_consistency_exponent_correlation;
  /// Numbers that failed in some replicates: (name, failed fraction).
  std::vector<std::pair<std::string, double>> failures;
};

/// `estimate` is fit_sweep of the original sweep (it gives the layout);
/// `progress(done)` is called as replicates complete (from one thread at a time).
BootstrapResult bootstrap(const SweepFit& estimate, const Resampler& resampler,
                          const BootstrapOptions& options,
                          const std::function<void(std::size_t)>& progress = {});

}  // namespace softglass::bridge
