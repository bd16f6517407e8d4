// `lognormal`: ln R ~ N(0, s²) cut at ± cut·s, with s chosen so that sd/mean is
// d after the cut (the final rescaling sets the mean to 1).
#include <cmath>

#include "micro/geometry/radii/truncated_normal.h"
#include "micro/geometry/radius_distribution.h"

namespace softglass::micro {
namespace {

// Width s such that sd/mean of R is `target`: CV² = M(2s)/M(s)² − 1 increases
// with s; bisection.
double lognormal_width(double target, double c) {
  const auto cv = [c](double s) {
    return std::sqrt(truncated_normal_mgf(2 * s, c) / std::pow(truncated_normal_mgf(s, c), 2) -
                     1.0);
  };
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (cv(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

class Lognormal final : public RadiusShape {
 public:
  // Never below zero: e^{−cut·s} > 0 (relative to the median, not the mean).
  double smallest(double, double) const override { return 1.0; }
  void sample(std::vector<double>& radii, double d, double cut,
              std::mt19937_64& rng) const override {
    const double s = d > 0.0 ? lognormal_width(d, cut) : 0.0;
    std::normal_distribution<double> normal(0.0, 1.0);
    for (double& r : radii) r = std::exp(s * truncated_normal(normal, rng, cut));
  }
};

std::unique_ptr<RadiusShape> make(const RadiusDistribution&) {
  return std::make_unique<Lognormal>();
}

}  // namespace

RadiusShapeEntry lognormal_radii() {
  return {"lognormal", "ln R normal with sd sqrt(ln(1 + d^2)), truncated likewise", {}, make};
}

}  // namespace softglass::micro
