#include "bridge/material/interpolation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

constexpr double kSamePhi = 1e-9;

// g″ at interior point j from its leave-one-out residual (second divided difference).
double curvature(const std::vector<double>& phi, const std::vector<Estimate>& g, std::size_t j) {
  const double right = (g[j + 1].value - g[j].value) / (phi[j + 1] - phi[j]);
  const double left = (g[j].value - g[j - 1].value) / (phi[j] - phi[j - 1]);
  return 2.0 * (right - left) / (phi[j + 1] - phi[j - 1]);
}

}  // namespace

bool is_simulated(const std::vector<double>& phi, double at) {
  return std::any_of(phi.begin(), phi.end(),
                     [&](double p) { return std::abs(p - at) <= kSamePhi; });
}

Interpolated interpolate(const std::vector<double>& phi, const std::vector<Estimate>& g,
                         double at) {
  const std::size_t n = phi.size();
  for (std::size_t j = 0; j < n; ++j)
    if (std::abs(phi[j] - at) <= kSamePhi) return {g[j].value, g[j].error, 0.0};
  require(n >= 2, "interpolation in phi needs at least two volume fractions");

  // The interval [φ_a, φ_b] holding `at`, or the nearest one outside the range.
  std::size_t a = 0;
  while (a + 2 < n && at > phi[a + 1]) ++a;
  const std::size_t b = a + 1;
  const double wb = (at - phi[a]) / (phi[b] - phi[a]), wa = 1.0 - wb;

  Interpolated out;
  out.value = wa * g[a].value + wb * g[b].value;
  out.statistical = std::hypot(wa * g[a].error, wb * g[b].error);
  double bend = -1.0;
  for (std::size_t j : {a, b})
    if (j >= 1 && j + 1 < n) bend = std::max(bend, std::abs(curvature(phi, g, j)));
  out.interpolation = bend < 0 ? std::numeric_limits<double>::quiet_NaN()
                               : 0.5 * bend * std::abs((at - phi[a]) * (phi[b] - at));
  return out;
}

}  // namespace softglass::bridge
