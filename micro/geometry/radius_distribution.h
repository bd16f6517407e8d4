// Particle radii with a prescribed polydispersity (standard deviation / mean).
//
// Radii are drawn from the chosen distribution and rescaled so that their sample
// mean is exactly 1: the mean radius R is the unit of length. Truncation narrows
// a distribution; the gaussian and lognormal widths are set so that sd/mean is
// the requested polydispersity after truncation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace softglass::micro {

enum class RadiusShape { gaussian, uniform, lognormal, bidisperse };

struct RadiusDistribution {
  RadiusShape shape = RadiusShape::gaussian;
  double polydispersity = 0.10;    // standard deviation / mean of the radius
  double truncation_sigmas = 2.5;  // gaussian and lognormal are cut at ± this many σ

  /// Throws InputError when the parameters would allow non-positive radii.
  void validate() const;
};

RadiusShape parse_radius_shape(const std::string& name);
std::string to_string(RadiusShape shape);

/// n radii, reproducible from `seed`, with sample mean exactly 1.
std::vector<double> sample_radii(std::size_t n, const RadiusDistribution& distribution,
                                 std::uint64_t seed);

}  // namespace softglass::micro
