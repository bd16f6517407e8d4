// Particle radii with a prescribed polydispersity (standard deviation / mean).
//
// Radii are drawn from the chosen shape of distribution and rescaled so that
// their sample mean is exactly 1: the mean radius R is the unit of length.
// Truncation narrows a distribution; the gaussian and lognormal widths are set
// so that sd/mean is the requested polydispersity after truncation.
//
// A shape is one file in geometry/radii/ — a class deriving from RadiusShape
// and a function returning its registry entry (RadiusShapeEntry
// <name>_radii()) — plus one line in radii/registered_shapes.h.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "common/registry.h"

namespace softglass::micro {

struct RadiusDistribution {
  std::string shape = "gaussian";  // a registered shape (radius_shapes())
  double polydispersity = 0.10;    // standard deviation / mean of the radius
  double truncation_sigmas = 2.5;  // gaussian and lognormal are cut at ± this many σ

  /// Throws InputError for an unknown shape or parameters that would allow
  /// non-positive radii.
  void validate() const;
};

/// A shape of radius distribution, before the rescaling to mean 1.
class RadiusShape {
 public:
  virtual ~RadiusShape() = default;
  /// The smallest radius it can draw, relative to its mean, at polydispersity
  /// `d` and truncation `cut` (standard deviations).
  virtual double smallest(double d, double cut) const = 0;
  /// Fills `radii` (sd/mean = d) from `rng`.
  virtual void sample(std::vector<double>& radii, double d, double cut,
                      std::mt19937_64& rng) const = 0;
};

using RadiusShapeEntry = ComponentEntry<RadiusShape, RadiusDistribution>;

/// Every shape (radii/registered_shapes.h).
const Registry<RadiusShapeEntry>& radius_shapes();

/// n radii, reproducible from `seed`, with sample mean exactly 1.
std::vector<double> sample_radii(std::size_t n, const RadiusDistribution& distribution,
                                 std::uint64_t seed);

}  // namespace softglass::micro
