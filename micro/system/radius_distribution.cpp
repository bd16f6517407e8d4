#include "micro/system/radius_distribution.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "common/errors.h"

namespace softglass::micro {

RadiusShape parse_radius_shape(const std::string& name) {
  if (name == "gaussian") return RadiusShape::gaussian;
  if (name == "uniform") return RadiusShape::uniform;
  if (name == "lognormal") return RadiusShape::lognormal;
  if (name == "bidisperse") return RadiusShape::bidisperse;
  throw InputError(fmt::format(
      "radius distribution '{}' is unknown; allowed: gaussian, uniform, lognormal, bidisperse", name));
}

std::string to_string(RadiusShape shape) {
  switch (shape) {
    case RadiusShape::gaussian: return "gaussian";
    case RadiusShape::uniform: return "uniform";
    case RadiusShape::lognormal: return "lognormal";
    case RadiusShape::bidisperse: return "bidisperse";
  }
  return "?";
}

double RadiusDistribution::max_relative_radius() const {
  const double d = polydispersity;
  switch (shape) {
    case RadiusShape::gaussian: return 1.0 + truncation_sigmas * d;
    case RadiusShape::uniform: return 1.0 + std::sqrt(3.0) * d;
    case RadiusShape::bidisperse: return 1.0 + d;
    case RadiusShape::lognormal: {
      const double s = std::sqrt(std::log1p(d * d));
      return std::exp(-0.5 * s * s + truncation_sigmas * s);
    }
  }
  return 1.0;
}

void RadiusDistribution::validate() const {
  require(std::isfinite(polydispersity) && polydispersity >= 0.0 && polydispersity <= 0.3,
          fmt::format("polydispersity = {} is outside [0, 0.3]", polydispersity));
  require(std::isfinite(truncation_sigmas) && truncation_sigmas >= 1.0 && truncation_sigmas <= 5.0,
          fmt::format("truncation = {} standard deviations is outside [1, 5]", truncation_sigmas));
  const double smallest = shape == RadiusShape::gaussian   ? 1.0 - truncation_sigmas * polydispersity
                          : shape == RadiusShape::uniform  ? 1.0 - std::sqrt(3.0) * polydispersity
                          : shape == RadiusShape::bidisperse ? 1.0 - polydispersity
                                                             : 1.0;
  require(smallest > 0.05,
          fmt::format("polydispersity = {} with the {} distribution allows radii below 5 % of the "
                      "mean (smallest {}); lower the polydispersity or the truncation",
                      polydispersity, to_string(shape), smallest));
}

std::vector<double> sample_radii(std::size_t n, const RadiusDistribution& distribution,
                                 std::uint64_t seed) {
  distribution.validate();
  std::mt19937_64 rng(seed);
  const double d = distribution.polydispersity;
  const double cut = distribution.truncation_sigmas;
  std::vector<double> radii(n);

  switch (distribution.shape) {
    case RadiusShape::gaussian: {
      std::normal_distribution<double> normal(0.0, 1.0);
      for (double& r : radii) {
        double z;
        do z = normal(rng);
        while (std::abs(z) > cut);
        r = 1.0 + d * z;
      }
      break;
    }
    case RadiusShape::uniform: {
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      for (double& r : radii) r = 1.0 + std::sqrt(3.0) * d * uniform(rng);
      break;
    }
    case RadiusShape::lognormal: {
      // ln R ~ N(μ, s²) with s² = ln(1 + d²), μ = −s²/2: mean 1, sd d.
      const double s = std::sqrt(std::log1p(d * d));
      std::normal_distribution<double> normal(0.0, 1.0);
      for (double& r : radii) {
        double z;
        do z = normal(rng);
        while (std::abs(z) > cut);
        r = std::exp(-0.5 * s * s + s * z);
      }
      break;
    }
    case RadiusShape::bidisperse: {
      // Equal numbers of the two sizes 1 ± d (sd = d exactly for even n), in random order.
      for (std::size_t i = 0; i < n; ++i) radii[i] = (i % 2 == 0) ? 1.0 - d : 1.0 + d;
      std::shuffle(radii.begin(), radii.end(), rng);
      break;
    }
  }

  if (n > 0) {
    const double mean = std::accumulate(radii.begin(), radii.end(), 0.0) / static_cast<double>(n);
    for (double& r : radii) r /= mean;
  }
  return radii;
}

}  // namespace softglass::micro
