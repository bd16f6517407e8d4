// Values known at the simulated volume fractions, wanted at another φ.
//
// Piecewise-linear interpolation between the two neighbouring φ (linear
// extrapolation from the two nearest outside the range). Two errors:
//
// statistical — the neighbours' own errors, propagated through the weights:
//     g(φ) = w_a g_a + w_b g_b,  var = w_a² s_a² + w_b² s_b²
// (different φ come from different packings, so their errors are independent);
//
// interpolation — what the straight line misses where g curves. Leaving an
// interior point φ_j out and predicting it from its neighbours misses by
//     r_j = g_j − (linear from j−1, j+1) = −½ g″ (φ_j − φ_{j−1})(φ_{j+1} − φ_j),
// so each leave-one-out residual measures the local curvature g″_j. The line
// between φ_a and φ_b then misses g at φ by ½ |g″| |(φ − φ_a)(φ_b − φ)|, with |g″|
// the larger of the curvatures measured at φ_a and φ_b (those that are
// interior). It vanishes at the simulated φ, grows towards the middle of an
// interval and, outside the range, quadratically with the distance. The
// curvature estimate carries the statistical noise of the three values, which
// makes it conservative. With two volume fractions there is no curvature to
// measure and the interpolation error is unknown (NaN).
#pragma once

#include <vector>

#include "bridge/io/flow_curve_table.h"

namespace softglass::bridge {

struct Interpolated {
  double value = 0.0;
  double statistical = 0.0;    // one standard deviation
  double interpolation = 0.0;  // estimated magnitude; NaN when unknown
};

/// `phi` increasing (at least one value), `g` the estimates at those φ. With
/// one φ only `at` must be that φ.
Interpolated interpolate(const std::vector<double>& phi, const std::vector<Estimate>& g, double at);

/// Whether `at` coincides with one of `phi` (within 1e-9).
bool is_simulated(const std::vector<double>& phi, double at);

}  // namespace softglass::bridge
