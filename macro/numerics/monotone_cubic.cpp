#include "macro/numerics/monotone_cubic.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::macro::numerics {

namespace {

// The cubic Hermite basis on t ∈ [0, 1] of an interval of width h: value and
// derivative in x of y0 h00 + h d0 h10 + y1 h01 + h d1 h11.
struct Hermite {
  double y0, y1, d0, d1, h;

  double value(double t) const {
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * y1 +
           (t3 - t2) * h * d1;
  }
  double derivative(double t) const {
    const double t2 = t * t;
    return ((6 * t2 - 6 * t) * y0 + (-6 * t2 + 6 * t) * y1) / h + (3 * t2 - 4 * t + 1) * d0 +
           (3 * t2 - 2 * t) * d1;
  }
};

}  // namespace

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  require(x_.size() >= 2 && x_.size() == y_.size(),
          fmt::format("monotone cubic: {} nodes and {} values; need the same number, at least 2",
                      x_.size(), y_.size()));
  for (std::size_t k = 0; k < x_.size(); ++k) {
    require(std::isfinite(x_[k]) && std::isfinite(y_[k]),
            fmt::format("monotone cubic: node {} ({}, {}) is not finite", k, x_[k], y_[k]));
    if (k > 0)
      require(x_[k] > x_[k - 1],
              fmt::format("monotone cubic: nodes not strictly increasing at {} ({} after {})", k,
                          x_[k], x_[k - 1]));
  }
  const std::size_t m = x_.size();
  std::vector<double> h(m - 1), delta(m - 1);
  for (std::size_t k = 0; k + 1 < m; ++k) {
    h[k] = x_[k + 1] - x_[k];
    delta[k] = (y_[k + 1] - y_[k]) / h[k];
  }
  d_.assign(m, 0.0);
  d_.front() = delta.front();
  d_.back() = delta.back();
  for (std::size_t k = 1; k + 1 < m; ++k) {
    if (delta[k - 1] * delta[k] <= 0.0) continue;
    const double w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
    d_[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
  }
}

std::size_t MonotoneCubic::interval(double x) const {
  const auto above = std::upper_bound(x_.begin(), x_.end(), x);
  const std::size_t k = above == x_.begin() ? 0 : std::size_t(above - x_.begin()) - 1;
  return std::min(k, x_.size() - 2);
}

std::pair<double, double> MonotoneCubic::value_and_derivative(double x) const {
  const std::size_t k = interval(x);
  const Hermite c{y_[k], y_[k + 1], d_[k], d_[k + 1], x_[k + 1] - x_[k]};
  const double t = (x - x_[k]) / c.h;
  return {c.value(t), c.derivative(t)};
}

double MonotoneCubic::inverse(double target) const {
  const auto above = std::upper_bound(y_.begin(), y_.end(), target);
  std::size_t k = above == y_.begin() ? 0 : std::size_t(above - y_.begin()) - 1;
  k = std::min(k, y_.size() - 2);
  const Hermite c{y_[k], y_[k + 1], d_[k], d_[k + 1], x_[k + 1] - x_[k]};
  // Newton on t ∈ [0, 1], kept inside a shrinking bracket (the cubic is
  // increasing there, so the bracket always holds the root); bisection when a
  // Newton step would leave it. Quadratic convergence, so 60 steps is a bound
  // that is never met before the bracket falls to a few ulps.
  double lo = 0.0, hi = 1.0, t = c.y1 > c.y0 ? (target - c.y0) / (c.y1 - c.y0) : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  for (int step = 0; step < 60 && hi - lo > 4e-16; ++step) {
    const double f = c.value(t) - target;
    if (f == 0.0) break;
    (f < 0.0 ? lo : hi) = t;
    const double slope = c.derivative(t) * c.h;
    const double next = slope > 0.0 ? t - f / slope : 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-16) break;  // Newton has converged
    t = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return x_[k] + t * c.h;
}

}  // namespace softglass::macro::numerics
