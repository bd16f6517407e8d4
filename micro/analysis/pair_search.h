// Every pair closer than a distance r_max, through the nearest Lees–Edwards
// image: the pair statistics of structure analysis need all neighbours, not
// only contacts. Uses the cell-grid neighbour list when the cell is large
// enough for it (L ≥ 3 (2 R_max + r_max)) and all pairs otherwise.
#pragma once

#include <functional>
#include <span>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

/// Calls `visit(i, j, d)` once for every pair i < j with |d| < r_max, where
/// d = x_i − x_j through the nearest image. Requires r_max < L/2.
void for_each_pair_within(const LeesEdwardsBox& box, std::span<const Vec3> x,
                          std::span<const double> radius, double r_max,
                          const std::function<void(std::size_t, std::size_t, const Vec3&)>& visit);

}  // namespace softglass::micro
