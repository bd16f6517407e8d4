// A shape-preserving C¹ interpolant of tabulated data: the monotone piecewise
// cubic Hermite interpolant of Fritsch & Carlson (SIAM J. Numer. Anal. 17, 238
// (1980)), with the node slopes of Fritsch & Butland (SIAM J. Sci. Stat.
// Comput. 5, 300 (1984)) — "PCHIP".
//
// On each interval [x_k, x_{k+1}] (width h_k, secant δ_k = (y_{k+1} − y_k)/h_k)
// the interpolant is the cubic with the node values y_k, y_{k+1} and the node
// slopes d_k, d_{k+1}. The slopes decide its shape:
//   interior  d_k = 0 where δ_{k−1} δ_k ≤ 0 (a local extremum of the data),
//             else the weighted harmonic mean
//                 d_k = (w₁ + w₂) / (w₁/δ_{k−1} + w₂/δ_k),
//                 w₁ = 2h_k + h_{k−1},  w₂ = h_k + 2h_{k−1};
//   ends      the end secants, d_0 = δ_0 and d_{M−1} = δ_{M−2}.
// The harmonic mean lies between 0 and 3 min(δ_{k−1}, δ_k), which is Fritsch &
// Carlson's sufficient condition for the cubic to be monotone on both
// intervals: monotone data give a monotone interpolant, and it never
// overshoots the data (no new extrema). Where the data lie on a straight line
// every δ is the same, so every d is too and the interpolant *is* that line —
// the property the tabulated flow law relies on to reproduce a power law
// exactly (tabulated_law.h). The end slopes are the end secants, not a
// three-point estimate, so that a continuation beyond the data with the end
// slope (the callers' extrapolation) keeps the sign of the last interval.
#pragma once

#include <utility>
#include <vector>

namespace softglass::macro::numerics {

class MonotoneCubic {
 public:
  /// Nodes x strictly increasing (at least two), values y of the same length,
  /// all finite; InputError otherwise.
  MonotoneCubic(std::vector<double> x, std::vector<double> y);

  /// The interpolant at x_0 ≤ x ≤ x_{M−1}; outside, the cubic of the end
  /// interval would be extrapolated, so callers handle the outside themselves.
  double value(double x) const { return value_and_derivative(x).first; }
  /// Its derivative there.
  double derivative(double x) const { return value_and_derivative(x).second; }
  /// Both, from one look-up of the interval.
  std::pair<double, double> value_and_derivative(double x) const;

  const std::vector<double>& nodes() const { return x_; }
  const std::vector<double>& values() const { return y_; }
  /// The node slopes d_k.
  const std::vector<double>& slopes() const { return d_; }

  /// The x in [x_k, x_{k+1}] with value(x) = target, for strictly increasing
  /// data and y_0 ≤ target ≤ y_{M−1} (TOMS 748 on the interval that brackets it).
  double inverse(double target) const;

 private:
  std::vector<double> x_, y_, d_;

  /// The interval k with x_k ≤ x ≤ x_{k+1} (the end ones for x outside).
  std::size_t interval(double x) const;
};

}  // namespace softglass::macro::numerics
