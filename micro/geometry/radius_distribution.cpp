#include "micro/geometry/radius_distribution.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "common/errors.h"

namespace softglass::micro {

namespace {

// Standard normal distribution function.
double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::numbers::sqrt2);
}

// Variance of a standard normal truncated to [−c, c]: 1 − 2cφ(c)/(2Φ(c) − 1).
double truncated_normal_variance(double c) {
  const double density = std::exp(-0.5 * c * c) / std::sqrt(2.0 * std::numbers::pi);
  return 1.0 - 2.0 * c * density / (2.0 * normal_cdf(c) - 1.0);
}

// E[e^{tZ}] for Z standard normal truncated to [−c, c].
double truncated_normal_mgf(double t, double c) {
  return std::exp(0.5 * t * t) * (normal_cdf(c - t) - normal_cdf(-c - t)) /
         (2.0 * normal_cdf(c) - 1.0);
}

// Width s of ln R ~ N(·, s²) truncated at ±c s such that sd/mean of R is `target`:
// CV² = M(2s)/M(s)² − 1 increases with s; bisection.
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

}  // namespace

RadiusShape parse_radius_shape(const std::string& name) {
  if (name == "gaussian") return RadiusShape::gaussian;
  if (name == "uniform") return RadiusShape::uniform;
  if (name == "lognormal") return RadiusShape::lognormal;
  if (name == "bidisperse") return RadiusShape::bidisperse;
  throw InputError(fmt::format(
      "radius distribution '{}' is unknown; allowed: gaussian, uniform, lognormal, bidisperse",
      name));
}

std::string to_string(RadiusShape shape) {
  switch (shape) {
    case RadiusShape::gaussian:
      return "gaussian";
    case RadiusShape::uniform:
      return "uniform";
    case RadiusShape::lognormal:
      return "lognormal";
    case RadiusShape::bidisperse:
      return "bidisperse";
  }
  return "?";
}

void RadiusDistribution::validate() const {
  require(std::isfinite(polydispersity) && polydispersity >= 0.0 && polydispersity <= 0.3,
          fmt::format("polydispersity = {} is outside [0, 0.3]", polydispersity));
  require(std::isfinite(truncation_sigmas) && truncation_sigmas >= 1.0 && truncation_sigmas <= 5.0,
          fmt::format("truncation = {} standard deviations is outside [1, 5]", truncation_sigmas));
  const double smallest = shape == RadiusShape::gaussian
                              ? 1.0 - truncation_sigmas * polydispersity /
                                          std::sqrt(truncated_normal_variance(truncation_sigmas))
                          : shape == RadiusShape::uniform    ? 1.0 - std::sqrt(3.0) * polydispersity
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
      // The cut narrows the distribution; widen it so that the sd is d.
      const double width = d / std::sqrt(truncated_normal_variance(cut));
      std::normal_distribution<double> normal(0.0, 1.0);
      for (double& r : radii) {
        double z;
        do z = normal(rng);
        while (std::abs(z) > cut);
        r = 1.0 + width * z;
      }
      break;
    }
    case RadiusShape::uniform: {
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      for (double& r : radii) r = 1.0 + std::sqrt(3.0) * d * uniform(rng);
      break;
    }
    case RadiusShape::lognormal: {
      // ln R ~ N(0, s²) cut at ± cut·s, s chosen so that sd/mean is d after the
      // cut (the final rescaling sets the mean to 1).
      const double s = d > 0.0 ? lognormal_width(d, cut) : 0.0;
      std::normal_distribution<double> normal(0.0, 1.0);
      for (double& r : radii) {
        double z;
        do z = normal(rng);
        while (std::abs(z) > cut);
        r = std::exp(s * z);
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
