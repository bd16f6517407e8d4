// The particles: positions, radii and the per-particle state that moves with them.
//
// Arrays are permuted together when particles are reordered in space (for cache
// locality); `label` keeps each particle's original index for output.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

struct Particles {
  std::vector<Vec3> position;        // in the primary cell, units of the mean radius R
  std::vector<double> radius;        // units of R (mean 1)
  std::vector<Vec3> velocity;        // fluctuation u − u∞ (or the minimiser's velocity)
  std::vector<std::uint32_t> label;  // original index

  Particles() = default;
  Particles(std::vector<Vec3> positions, std::vector<double> radii);

  std::size_t size() const { return position.size(); }
  double max_radius() const;
  double total_volume() const;  // Σ (4/3)π R³

  /// Applies `order` (new index → old index) to every per-particle array.
  void permute(std::span<const std::uint32_t> order);
  /// Positions, radii and velocities in the original labelling.
  Particles in_label_order() const;
};

}  // namespace softglass::micro
