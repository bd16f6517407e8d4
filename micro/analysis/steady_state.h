// Steady-state analysis of simulation time series: transient removal and the
// mean with its standard error for strongly correlated data.
//
// A sheared glass starts from rest: the stress rises, overshoots, and settles
// onto a noisy plateau whose fluctuations are correlated over many samples.
// Two questions have to be answered, at run time (may we stop?) and
// afterwards (what goes in the table, with which error bar?):
//
//  1. Where does the transient end?  MSER-m (White 1997; White, Cobb & Spratt
//     2000) picks the truncation point that minimises the estimated variance
//     of the mean of what is left, trading bias (keeping transient samples)
//     against noise (throwing samples away).
//  2. What is the standard error of the mean of the stationary rest?  Naive
//     σ/√n underestimates it by √(2τ_int) for correlated data.  Blocking
//     (Flyvbjerg & Petersen 1989) averages neighbouring pairs until the block
//     means are uncorrelated; Jonsson's M test (Phys. Rev. E 98, 043304
//     (2018)) decides automatically, with a χ² hypothesis test, when that is.
//
// All inputs are equally spaced samples (in strain or time); the functions do
// not care about the spacing.  Every function rejects empty or too short input
// and non-finite values (NaN, ±inf) with std::invalid_argument.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace softglass::micro {

/// MSER needs at least this many batches (20 samples for MSER-5).
inline constexpr std::size_t kMserMinBatches = 4;
/// Blocking needs at least this many samples (two levels of 4 and 2 blocks).
inline constexpr std::size_t kBlockingMinSamples = 4;
/// An error bar from fewer blocks than this is flagged as unreliable: its own
/// relative uncertainty 1/√(2(blocks−1)) would exceed ≈ 18 %.
inline constexpr std::size_t kMinReliableBlocks = 16;

/// MSER-m truncation point, in samples.
///
/// The series is cut into k = ⌊n/batch⌋ batches of `batch` consecutive samples
/// (a final incomplete batch is ignored by the statistic); b_j is the mean of
/// batch j.  For a candidate truncation of d batches,
///
///     MSER(d) = Σ_{j=d}^{k−1} (b_j − b̄_d)² / (k − d)²,   b̄_d = mean of b_d … b_{k−1},
///
/// i.e. (sample variance of the retained batch means)/(number retained): an
/// estimate of the squared standard error of the truncated mean that also
/// grows when retained transient batches inflate the spread.  The rule picks
/// the smallest d minimising MSER(d) over d ∈ [0, ⌊k/2⌋] only: a minimum in
/// the second half means the run is too short to tell the transient from the
/// steady state (and for d → k−1 the statistic trivially tends to zero).
/// Caveat: when the transient does last more than half the run, the
/// restricted minimum can be anywhere, even at d = 0 (a long plateau before a
/// late drop looks "less variable" than the mixture).  Use
/// analyse_steady_state, whose `transient_unresolved` flag checks for that.
/// Known limitation: MSER stops roughly where the transient has decayed to the
/// noise level of a batch mean, so the bias left in the truncated mean,
/// relative to its standard error, grows like τ/√(n·g) (τ the relaxation time,
/// g = 2τ_int the statistical inefficiency, both in samples).  For AR(1)
/// noise with g = 19 and n = 2^14 it was ≈ 0.2, 0.7, 1.9 SE at τ/n = 0.5, 2, 5 %.
/// batch = 5 is the standard MSER-5.  Requires batch ≥ 1 and k ≥ kMserMinBatches.
std::size_t mser_truncation(std::span<const double> x, std::size_t batch = 5);

/// Mean of a stationary series with its standard error.
struct MeanEstimate {
  double mean = 0.0;            // arithmetic mean of all samples
  double standard_error = 0.0;  // estimated standard deviation of `mean`
  std::size_t samples = 0;      // number of samples averaged
  std::size_t block_size = 1;   // 2^k: samples per block at the chosen blocking level
  bool reliable = false;        // M test passed and at least kMinReliableBlocks blocks
};

/// Mean and standard error by automated blocking (Jonsson 2018).
///
/// The blocking analysis uses the most recent 2^d samples, 2^d the largest
/// power of two ≤ n (for a steady-state run the latest data are the most
/// stationary).  Level 0 is that series; level i+1 averages neighbouring pairs
/// of level i, so level i has n_i = 2^(d−i) block means of 2^i samples each.
/// At each level, with x̄ the mean (identical at every level),
///
///     σ̂_i² = (1/n_i) Σ_t (x_t − x̄)²,   γ̂_i = (1/n_i) Σ_{t=1}^{n_i−1} (x_t − x̄)(x_{t+1} − x̄),
///
///     M_j = Σ_{i=j}^{d−1} n_i [ (n_i − 1) σ̂_i² / n_i² + γ̂_i ]² / σ̂_i⁴ .
///
/// If the block means from level j on are uncorrelated, each term is
/// asymptotically χ²₁ (√n_i ρ̂₁ is standard normal once its bias −(n_i−1)/n_i²
/// is removed) and the levels are independent, so M_j ~ χ²_{d−j}.  The chosen
/// level is the smallest j ≤ d−2 with M_j < q_{0.99}(χ²_{d−j}).  Then
///
///     SE² = [σ̂_j² / (n_j − 1)] · 2^d / n
///
/// (Flyvbjerg–Petersen's unbiased block variance, rescaled from the 2^d
/// analysed samples to all n samples: the variance of a mean of a stationary
/// series scales as 1/length once length ≫ the correlation time).  The mean is
/// the mean of all n samples.  If no level passes, the deepest level with at
/// least kMinReliableBlocks blocks is reported (a lower bound on the error)
/// and `reliable` is false.  Requires n ≥ kBlockingMinSamples.
///
/// Known limitation: the M test stops as soon as the residual correlation of
/// the block means is statistically invisible, not when it is negligible, so
/// the error is biased low by roughly τ_int/(block size).  For AR(1) series
/// the mean ratio estimated/true SE was 0.91 (φ = 0.9, n = 2^14) and 0.47,
/// 0.66, 0.80, 0.87 for φ = 0.99 at n = 2^10, 2^12, 2^14, 2^16; with fewer than
/// ~100 correlation times the test also has little power, so `reliable` can
/// be true although the error is too small.
MeanEstimate block_average(std::span<const double> x);

/// Geweke-type stationarity check of a series judged stationary: the mean of its
/// first 10 % against that of its last 50 %,
///     z = (m_first − m_last) / (SE_last √(n_last/n_first + 1)),
/// with SE_last the blocking error of the last half: both segments' errors come
/// from its long-run variance (Geweke 1992), since blocking a short first
/// segment alone underestimates its error when it spans few correlation times,
/// and the whole window's variance would absorb the drift being tested.
/// |z| > 3 says the "stationary" part still drifts — a slow transient, or a
/// slow change of state such as shear-induced layering — which MSER and
/// blocking alone do not catch. Returns 0 when a part is too short to judge.
double drift_statistic(std::span<const double> x);

/// Joint steady-state analysis of several observables recorded together.
struct SteadyStateAnalysis {
  std::size_t total_samples = 0;         // length of every observable
  std::size_t transient_samples = 0;     // max over observables of the MSER-5 truncation
  std::size_t stationary_samples = 0;    // total_samples − transient_samples
  std::vector<std::size_t> truncations;  // per observable MSER-5 truncation, in samples
  std::vector<MeanEstimate> estimates;   // per observable, block_average of the stationary part
  bool enough_samples = false;           // stationary_samples ≥ the requested minimum
  /// For some observable the MSER statistic, minimised over all truncations
  /// that keep ≥ kMserMinBatches batches, is smallest in the second half of the
  /// run: the transient may not be over (White, Cobb & Spratt 2000: "run too
  /// short").  `transient_samples` is then not trustworthy.
  bool transient_unresolved = false;

  /// The run can be stopped: transient resolved, enough stationary data, and
  /// every error bar reliable.
  [[nodiscard]] bool converged() const noexcept;
};

/// Analyses observables sampled at the same instants (e.g. σ, N1, N2).  The
/// run is stationary only when every observable is, so the transient is the
/// MAXIMUM of the individual MSER-5 truncations; each observable is then
/// block-averaged over the common stationary part [transient_samples, n).
/// Requires at least one observable, equal lengths, and n ≥ 5·kMserMinBatches.
SteadyStateAnalysis analyse_steady_state(const std::vector<std::span<const double>>& observables,
                                         std::size_t min_stationary_samples);

/// A named mean with its error, e.g. σ of a run or G′ of a cycle average.
struct ObservableEstimate {
  std::string name;
  MeanEstimate estimate;
};
/// The estimate called `name` in `list`; std::invalid_argument if absent.
const MeanEstimate& find_estimate(const std::vector<ObservableEstimate>& list,
                                  const std::string& name);

}  // namespace softglass::micro
