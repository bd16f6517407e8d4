#include "micro/geometry/radius_distribution.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "common/errors.h"
#include "micro/geometry/radii/registered_shapes.h"

namespace softglass::micro {

#define SOFTGLASS_DECLARE_SHAPE(name) RadiusShapeEntry name##_radii();
SOFTGLASS_RADIUS_SHAPES(SOFTGLASS_DECLARE_SHAPE)
#undef SOFTGLASS_DECLARE_SHAPE

const Registry<RadiusShapeEntry>& radius_shapes() {
#define SOFTGLASS_LIST_SHAPE(name) name##_radii(),
  static const Registry<RadiusShapeEntry> registry("radius distribution",
                                                   {SOFTGLASS_RADIUS_SHAPES(SOFTGLASS_LIST_SHAPE)});
#undef SOFTGLASS_LIST_SHAPE
  return registry;
}

void RadiusDistribution::validate() const {
  require(std::isfinite(polydispersity) && polydispersity >= 0.0 && polydispersity <= 0.3,
          fmt::format("polydispersity = {} is outside [0, 0.3]", polydispersity));
  require(std::isfinite(truncation_sigmas) && truncation_sigmas >= 1.0 && truncation_sigmas <= 5.0,
          fmt::format("truncation = {} standard deviations is outside [1, 5]", truncation_sigmas));
  const double smallest =
      radius_shapes().at(shape).make(*this)->smallest(polydispersity, truncation_sigmas);
  require(smallest > 0.05,
          fmt::format("polydispersity = {} with the {} distribution allows radii below 5 % of the "
                      "mean (smallest {}); lower the polydispersity or the truncation",
                      polydispersity, shape, smallest));
}

std::vector<double> sample_radii(std::size_t n, const RadiusDistribution& distribution,
                                 std::uint64_t seed) {
  distribution.validate();
  std::mt19937_64 rng(seed);
  std::vector<double> radii(n);
  radius_shapes()
      .at(distribution.shape)
      .make(distribution)
      ->sample(radii, distribution.polydispersity, distribution.truncation_sigmas, rng);
  if (n > 0) {
    const double mean = std::accumulate(radii.begin(), radii.end(), 0.0) / static_cast<double>(n);
    for (double& r : radii) r /= mean;
  }
  return radii;
}

}  // namespace softglass::micro
