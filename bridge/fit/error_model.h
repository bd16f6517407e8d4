// The standard errors of a simulated flow curve, smoothed along the curve.
//
// The table's standard errors come from a few packings (the paper: 5), and are
// uncertain themselves: s² has K − 1 degrees of freedom, so s is off by about
// ±35 % for K = 5 and the weight 1/s² has a heavy right tail. Used directly, a
// point whose error happens to come out small dominates its fit, and χ² has a
// mean of (K − 1)/(K − 3) = 2 times its degrees of freedom with a tail that
// makes a correct law "miss its data" (measured on synthetic sweeps: χ²/dof up
// to 12 for the true law).
//
// The bridge therefore models the errors along each curve: the relative error
// drifts as a power of the rate,
//     se_i = c |y_i| exp(a + b ln x_i),
// with (a, b) from a least-squares fit of ln(se_i/|y_i|) (the shape) and the
// level c² = mean of se_i² / (|y_i| exp(a + b ln x_i))², the pooled variance
// ratio, which is unbiased where a fit of logarithms is not (E ln s² lies
// ψ((K−1)/2) − ln((K−1)/2) = −0.27 below ln σ² for K = 5). The weights then
// rest on ν = Σ_i (K_i − 1) − 2 degrees of freedom (the shape costs two)
// instead of K − 1, and the curve's `error_dof` is set to ν (infinite when the
// points average single runs, whose errors come from long time series). The
// smoothed errors are the fit weights and the parametric bootstrap's noise.
// A curve with a zero value is left as it is.
#pragma once

#include <cstddef>
#include <vector>

#include "bridge/fit/curve.h"

namespace softglass::bridge {

/// `packings[i]` is the number K_i of runs averaged at point i.
void smooth_errors(Curve& curve, const std::vector<std::size_t>& packings);

}  // namespace softglass::bridge
