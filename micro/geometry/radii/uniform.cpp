// `uniform`: radii uniform on 1 ± √3 d (sd/mean = d), as the LAMMPS peer's input.
#include <cmath>

#include "micro/geometry/radius_distribution.h"

namespace softglass::micro {
namespace {

class Uniform final : public RadiusShape {
 public:
  double smallest(double d, double) const override { return 1.0 - std::sqrt(3.0) * d; }
  void sample(std::vector<double>& radii, double d, double, std::mt19937_64& rng) const override {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (double& r : radii) r = 1.0 + std::sqrt(3.0) * d * uniform(rng);
  }
};

std::unique_ptr<RadiusShape> make(const RadiusDistribution&) {
  return std::make_unique<Uniform>();
}

}  // namespace

RadiusShapeEntry uniform_radii() {
  return {"uniform", "uniform on 1 +- sqrt(3) d", {}, make};
}

}  // namespace softglass::micro
