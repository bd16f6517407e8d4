#include "micro/analysis/layering.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace softglass::micro {

Layering gradient_layering(std::span<const Vec3> positions, double side) {
  const int modes = std::max(1, static_cast<int>(std::floor(side)));
  std::vector<std::complex<double>> sum(modes + 1, 0.0);
  for (const Vec3& x : positions) {
    // exp(2πi m y/L) by repeated multiplication: one sincos per particle.
    const std::complex<double> phase = std::polar(1.0, 2.0 * std::numbers::pi * x.y() / side);
    std::complex<double> power = 1.0;
    for (int m = 1; m <= modes; ++m) {
      power *= phase;
      sum[m] += power;
    }
  }
  Layering best;
  const double n = static_cast<double>(positions.size());
  for (int m = 1; m <= modes; ++m) {
    const double s = std::norm(sum[m]) / n;
    if (s > best.order) best = {s, m};
  }
  return best;
}

}  // namespace softglass::micro
