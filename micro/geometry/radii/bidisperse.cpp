// `bidisperse`: equal numbers of the two sizes 1 ± d (sd = d exactly for even
// n), in random order.
#include <algorithm>

#include "micro/geometry/radius_distribution.h"

namespace softglass::micro {
namespace {

class Bidisperse final : public RadiusShape {
 public:
  double smallest(double d, double) const override { return 1.0 - d; }
  void sample(std::vector<double>& radii, double d, double, std::mt19937_64& rng) const override {
    for (std::size_t i = 0; i < radii.size(); ++i) radii[i] = (i % 2 == 0) ? 1.0 - d : 1.0 + d;
    std::shuffle(radii.begin(), radii.end(), rng);
  }
};

std::unique_ptr<RadiusShape> make(const RadiusDistribution&) {
  return std::make_unique<Bidisperse>();
}

}  // namespace

RadiusShapeEntry bidisperse_radii() {
  return {"bidisperse", "half 1 - d, half 1 + d", {}, make};
}

}  // namespace softglass::micro
