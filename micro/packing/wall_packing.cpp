#include "micro/packing/wall_packing.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "common/errors.h"

namespace softglass::micro {

double wall_cell_side(double volume, double volume_fraction, double slab) {
  // φ L² (L − s) grows monotonically for L > s; with c = (V/φ)^{1/3} it is
  // ≥ V at L = s + c, so the root lies in (s, s + c]: bisection.
  double low = slab, high = slab + std::cbrt(volume / volume_fraction);
  for (int it = 0; it < 200 && high - low > 1e-15 * high; ++it) {
    const double mid = 0.5 * (low + high);
    (volume_fraction * mid * mid * (mid - slab) < volume ? low : high) = mid;
  }
  return high;
}

WallPacking make_wall_packing(const PackingSpec& spec, std::shared_ptr<const ContactLaw> law,
                              const std::function<void(double)>& progress) {
  spec.validate();
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> radii = sample_radii(spec.particles, spec.radii, spec.seed);
  double volume = 0.0, max_radius = 0.0;
  for (double r : radii) {
    volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    max_radius = std::max(max_radius, r);
  }
  // 1e-9 R more than the least slab: the compression's rescalings must not
  // round it below (Walls::check_inside).
  const double slab = 2.0 * (max_radius + spec.skin) + 1e-9;
  const double side = wall_cell_side(volume, spec.volume_fraction, slab);
  const double gap = side - slab;
  require(gap >= kMinWallGap,
          fmt::format("walls: particles/number = {} at φ = {} leave a gap of {:.3g} R between the "
                      "walls, below {} R (two diameters); use more particles",
                      spec.particles, spec.volume_fraction, gap, kMinWallGap));

  // Start at φ₀ with every length scaled up by (φ/φ₀)^{1/3}; centres uniform
  // in the slab (the same streams as make_packing).
  const double scale = std::cbrt(spec.volume_fraction / spec.initial_volume_fraction);
  const Walls initial{scale * 0.5 * slab, scale * (side - 0.5 * slab)};
  std::mt19937_64 rng(spec.seed ^ 0x9e3779b97f4a7c15ull);
  std::uniform_real_distribution<double> across(0.0, scale * side), height(initial.lower, initial.upper);
  std::vector<Vec3> centres(spec.particles);
  for (Vec3& x : centres) {
    const double cx = across(rng), cy = height(rng);
    x = Vec3(cx, cy, across(rng));
  }
  ContactSystem system(Particles(std::move(centres), std::move(radii)),
                       LeesEdwardsBox(scale * side), std::move(law), spec.skin);
  system.set_walls(initial);
  const std::size_t iterations = compress(system, spec, progress);
  PackingReport report = finish_report(system, spec, iterations, start);
  return {{system.wrapped_in_label_order(), system.box(), report}, system.walls()};
}

}  // namespace softglass::micro
