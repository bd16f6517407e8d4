// Steady-state analysis: MSER-m truncation and Jonsson's automated blocking.
// The statistics are documented in steady_state.h; this file keeps to the
// numerical details.
#include "micro/analysis/steady_state.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <boost/math/distributions/chi_squared.hpp>

namespace softglass::micro {

namespace {

// Significance of the M test: the probability of blocking further than needed
// when the block means are already uncorrelated (Jonsson uses 1 %).
constexpr double kMTestConfidence = 0.99;

// A blocking level whose variance is this small relative to level 0 has
// cancelled exactly (e.g. a series alternating between two values): its block
// means are all equal, i.e. perfectly uncorrelated, and its M term is zero.
constexpr double kVanishingVarianceRatio = 1e-24;

void require_finite(std::span<const double> x, const std::string& context) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::isnan(x[i])) {
      throw std::invalid_argument(context + ": NaN at index " + std::to_string(i));
    }
    if (std::isinf(x[i])) {
      throw std::invalid_argument(context + ": infinite value at index " + std::to_string(i));
    }
  }
}

// Two-pass mean: the correction pass removes most of the rounding error of a
// plain sum when the mean is large compared with the fluctuations.
double mean_of(std::span<const double> x) {
  const auto n = static_cast<double>(x.size());
  double sum = 0.0;
  for (double v : x) sum += v;
  const double rough = sum / n;
  double correction = 0.0;
  for (double v : x) correction += v - rough;
  return rough + correction / n;
}

// Result of one MSER sweep: the rule's truncation (minimum over the first
// half) and the minimiser over the whole admissible range, d ≤ k − 4 (with
// fewer retained batches the statistic tends to zero for trivial reasons).
struct MserScan {
  std::size_t truncation = 0;  // samples
  bool minimum_in_second_half = false;
};

MserScan mser_scan(std::span<const double> x, std::size_t batch, const std::string& context) {
  if (batch == 0) throw std::invalid_argument(context + ": batch size must be positive");
  const std::size_t k = x.size() / batch;
  if (k < kMserMinBatches) {
    throw std::invalid_argument(context + ": series too short for MSER-" + std::to_string(batch) +
                                ": need at least " + std::to_string(kMserMinBatches * batch) +
                                " samples (" + std::to_string(kMserMinBatches) + " batches), got " +
                                std::to_string(x.size()));
  }

  std::vector<double> b(k);
  for (std::size_t j = 0; j < k; ++j) {
    double s = 0.0;
    for (std::size_t t = 0; t < batch; ++t) s += x[j * batch + t];
    b[j] = s / static_cast<double>(batch);
  }

  // Sweep d from k−1 down to 0, adding b_d to the retained suffix with
  // Welford's update (stable, no Σb² − (Σb)² cancellation).  `m2` is
  // Σ_{j≥d} (b_j − b̄_d)².  Ties are resolved towards the smaller d by `<=`.
  const std::size_t d_half = k / 2;
  const std::size_t d_last = k - kMserMinBatches;
  double mean = 0.0;
  double m2 = 0.0;
  double best_half = std::numeric_limits<double>::infinity();
  double best_all = std::numeric_limits<double>::infinity();
  std::size_t d_best_half = 0;
  std::size_t d_best_all = 0;
  for (std::size_t d = k; d-- > 0;) {
    const auto count = static_cast<double>(k - d);
    const double delta = b[d] - mean;
    mean += delta / count;
    m2 += delta * (b[d] - mean);
    const double statistic = m2 / (count * count);
    if (d <= d_last && statistic <= best_all) {
      best_all = statistic;
      d_best_all = d;
    }
    if (d <= d_half && statistic <= best_half) {
      best_half = statistic;
      d_best_half = d;
    }
  }
  return {d_best_half * batch, d_best_all > d_half};
}

MeanEstimate block_average_checked(std::span<const double> x, const std::string& context) {
  const std::size_t n = x.size();
  if (n < kBlockingMinSamples) {
    throw std::invalid_argument(context + ": series too short for blocking: need at least " +
                                std::to_string(kBlockingMinSamples) + " samples, got " +
                                std::to_string(n));
  }

  MeanEstimate result;
  result.samples = n;
  result.mean = mean_of(x);

  // The most recent 2^d samples, centred on their own mean (which every
  // blocking level shares, since pairwise averaging preserves it).
  const std::size_t analysed = std::bit_floor(n);
  const auto d = static_cast<std::size_t>(std::countr_zero(analysed));
  std::span<const double> tail = x.subspan(n - analysed);
  const double tail_mean = mean_of(tail);
  std::vector<double> y(tail.begin(), tail.end());
  for (double& v : y) v -= tail_mean;

  // Per level i = 0 … d−1 (n_i = 2^(d−i) ≥ 2): variance σ̂_i² and M term.
  std::vector<double> variance(d);
  std::vector<double> term(d);
  std::size_t len = analysed;
  for (std::size_t i = 0; i < d; ++i) {
    const auto ni = static_cast<double>(len);
    double s0 = 0.0;
    double s1 = 0.0;
    for (std::size_t t = 0; t < len; ++t) s0 += y[t] * y[t];
    for (std::size_t t = 0; t + 1 < len; ++t) s1 += y[t] * y[t + 1];
    const double var = s0 / ni;
    const double gamma = s1 / ni;
    variance[i] = var;
    if (i > 0 && var <= kVanishingVarianceRatio * variance[0]) {
      term[i] = 0.0;
    } else if (var > 0.0) {
      // Under "uncorrelated", E[γ̂] = −(n_i−1)σ²/n_i² and Var[γ̂] ≈ σ⁴/n_i.
      const double z = (ni - 1.0) * var / (ni * ni) + gamma;
      term[i] = ni * z * z / (var * var);
    } else {
      term[i] = 0.0;  // constant series (only possible at level 0): nothing to test
    }
    // Blocking transformation: x'_t = (x_{2t} + x_{2t+1}) / 2.
    for (std::size_t t = 0; t < len / 2; ++t) y[t] = 0.5 * (y[2 * t] + y[2 * t + 1]);
    len /= 2;
  }

  if (variance[0] == 0.0) {  // constant series: the mean is exact
    result.standard_error = 0.0;
    result.block_size = 1;
    result.reliable = true;
    return result;
  }

  // M_j = Σ_{i≥j} term_i, tested against χ²_{d−j} for j = 0 … d−2 (the last
  // level, 2 blocks, carries a constant term and cannot be used on its own).
  std::vector<double> m(d + 1, 0.0);
  for (std::size_t i = d; i-- > 0;) m[i] = m[i + 1] + term[i];
  bool passed = false;
  std::size_t level = 0;
  for (std::size_t j = 0; j + 2 <= d; ++j) {
    const boost::math::chi_squared chi2(static_cast<double>(d - j));
    if (m[j] < boost::math::quantile(chi2, kMTestConfidence)) {
      passed = true;
      level = j;
      break;
    }
  }
  if (!passed) {
    // Deepest level with ≥ kMinReliableBlocks blocks, i.e. 2^(d−j) ≥ 16.
    const std::size_t min_log2_blocks =
        static_cast<std::size_t>(std::countr_zero(std::bit_ceil(kMinReliableBlocks)));
    level = d > min_log2_blocks ? d - min_log2_blocks : 0;
    level = std::min(level, d - 2);
  }

  const std::size_t blocks = analysed >> level;
  const double block_variance = variance[level] / static_cast<double>(blocks - 1);
  result.standard_error =
      std::sqrt(block_variance * static_cast<double>(analysed) / static_cast<double>(n));
  result.block_size = std::size_t{1} << level;
  result.reliable = passed && blocks >= kMinReliableBlocks;
  return result;
}

}  // namespace

std::size_t mser_truncation(std::span<const double> x, std::size_t batch) {
  require_finite(x, "mser_truncation");
  return mser_scan(x, batch, "mser_truncation").truncation;
}

MeanEstimate block_average(std::span<const double> x) {
  require_finite(x, "block_average");
  return block_average_checked(x, "block_average");
}

bool SteadyStateAnalysis::converged() const noexcept {
  return enough_samples && !transient_unresolved &&
         std::all_of(estimates.begin(), estimates.end(),
                     [](const MeanEstimate& e) { return e.reliable; });
}

SteadyStateAnalysis analyse_steady_state(const std::vector<std::span<const double>>& observables,
                                         std::size_t min_stationary_samples) {
  const std::string context = "analyse_steady_state";
  if (observables.empty()) throw std::invalid_argument(context + ": no observables given");
  const std::size_t n = observables.front().size();
  for (std::size_t o = 0; o < observables.size(); ++o) {
    if (observables[o].size() != n) {
      throw std::invalid_argument(context + ": observable " + std::to_string(o) + " has " +
                                  std::to_string(observables[o].size()) +
                                  " samples, observable 0 has " + std::to_string(n));
    }
    require_finite(observables[o], context + ": observable " + std::to_string(o));
  }

  constexpr std::size_t batch = 5;  // MSER-5

  SteadyStateAnalysis result;
  result.total_samples = n;
  result.truncations.reserve(observables.size());
  for (std::size_t o = 0; o < observables.size(); ++o) {
    const MserScan scan =
        mser_scan(observables[o], batch, context + ": observable " + std::to_string(o));
    result.truncations.push_back(scan.truncation);
    result.transient_samples = std::max(result.transient_samples, scan.truncation);
    if (scan.minimum_in_second_half) result.transient_unresolved = true;
  }
  result.stationary_samples = n - result.transient_samples;
  result.enough_samples = result.stationary_samples >= min_stationary_samples;

  result.estimates.reserve(observables.size());
  for (std::size_t o = 0; o < observables.size(); ++o) {
    result.estimates.push_back(
        block_average_checked(observables[o].subspan(result.transient_samples),
                              context + ": observable " + std::to_string(o)));
  }
  return result;
}

double drift_statistic(std::span<const double> x) {
  const std::size_t first = x.size() / 10, last = x.size() / 2;
  if (first < kBlockingMinSamples) return 0.0;
  const auto mean = [](std::span<const double> part) {
    double sum = 0.0;
    for (double v : part) sum += v;
    return sum / static_cast<double>(part.size());
  };
  // Both segments' errors from the long-run variance of the last half, scaled
  // to each length: blocking the short first segment alone underestimates its
  // error, and the whole window's variance would absorb the drift itself.
  const MeanEstimate tail = block_average(x.last(last));
  const double ratio = static_cast<double>(last) / static_cast<double>(first);
  const double spread = tail.standard_error * std::sqrt(ratio + 1.0);
  return spread > 0.0 ? (mean(x.first(first)) - tail.mean) / spread : 0.0;
}

const MeanEstimate& find_estimate(const std::vector<ObservableEstimate>& list,
                                  const std::string& name) {
  for (const auto& o : list)
    if (o.name == name) return o.estimate;
  throw std::invalid_argument("no observable " + name);
}

}  // namespace softglass::micro
