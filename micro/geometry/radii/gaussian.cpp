// `gaussian` (default): normal radii cut at ± `truncation` standard deviations,
// widened so that the cut distribution has sd/mean = d.
#include "micro/geometry/radii/truncated_normal.h"
#include "micro/geometry/radius_distribution.h"

namespace softglass::micro {
namespace {

class Gaussian final : public RadiusShape {
 public:
  double smallest(double d, double cut) const override { return 1.0 - cut * width(d, cut); }
  void sample(std::vector<double>& radii, double d, double cut,
              std::mt19937_64& rng) const override {
    const double w = width(d, cut);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (double& r : radii) r = 1.0 + w * truncated_normal(normal, rng, cut);
  }

 private:
  // The cut narrows the distribution; widen it so that the sd is d.
  static double width(double d, double cut) {
    return d / std::sqrt(truncated_normal_variance(cut));
  }
};

std::unique_ptr<RadiusShape> make(const RadiusDistribution&) {
  return std::make_unique<Gaussian>();
}

}  // namespace

RadiusShapeEntry gaussian_radii() {
  return {"gaussian", "normal, truncated at +- 'truncation' standard deviations", {}, make};
}

}  // namespace softglass::micro
