// Replicates of a sweep for the bootstrap: the same state points, values redrawn.
//
// Packing bootstrap (with the per-packing companion table). The resampling unit
// is the packing: at every state point its K runs are drawn K times with
// replacement and averaged; G0 likewise over the distinct packings (seeds) of
// each φ. Rates are resampled independently of each other (a stratified
// bootstrap): after the transient a run at one rate has forgotten the packing
// it started from, so the runs of one seed at two rates are independent
// samples, and resampling them jointly would only make the error estimate
// noisier (K − 1 degrees of freedom for the whole curve instead of per point).
//
// The plain bootstrap of a mean of K values has variance (K − 1)/K · s²/K: too
// small by K/(K − 1), 25 % for the paper's K = 5. Every redrawn mean is
// therefore moved away from the sample mean by the factor √(K/(K − 1)),
//     x* = x̄ + √(K/(K − 1)) (mean of the draws − x̄),
// whose variance is exactly s²/K, the squared standard error of the average.
//
// The spread of each redrawn stress mean is then set by the smoothed standard
// error of its point (fit/error_model.h) rather than by its own K runs: the
// deviation from x̄ is scaled by se_smoothed/se_table. The K runs of one point
// give its variance with K − 1 = 4 degrees of freedom, so a parameter ruled
// by a few points (the yield stress: the lowest rates) would inherit an error
// resting on ~10 degrees of freedom and t-like tails (measured on synthetic
// sweeps: 8.3 % of the yield, consistency and exponent estimates beyond 2
// reported SE instead of 4.6 %; 7.0 % with the scaling); the smoothed errors
// rest on the whole curve. The shape of the packing distribution is kept. G0
// is resampled unscaled (one value per φ, nothing to pool over).
//
// Parametric bootstrap (the averaged table only). Every value is redrawn as a
// normal variable around the table's value with the table's standard error;
// this assumes Gaussian errors, independent between state points.
//
// Both keep the fit weights (the smoothed standard errors) of the original table.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bridge/io/flow_curve_table.h"
#include "bridge/sweep/sweep.h"

namespace softglass::bridge {

class Resampler {
 public:
  virtual ~Resampler() = default;
  /// A replicate of the sweep: same shape and weights, redrawn values.
  virtual Sweep draw(std::mt19937_64& rng) const = 0;
  /// What is resampled, for reports.
  virtual std::string description() const = 0;
};

std::unique_ptr<Resampler> make_parametric_resampler(const Sweep& sweep);

/// Quasi-static runs (γ̃ = 0) are checked against their rows but not resampled:
/// they are not fitted.
/// InputError unless the runs match the sweep: every run at a state point of
/// the table, as many runs as the table's packings at every point (at least 2 at γ̃ > 0),
/// at least 2 packings with a G0 per φ, the same quantities, and run means equal
/// to the table's values (within a hundredth of their standard errors).
std::unique_ptr<Resampler> make_packing_resampler(const Sweep& sweep,
                                                  const std::vector<PackingRun>& runs,
                                                  const std::string& source);

}  // namespace softglass::bridge
