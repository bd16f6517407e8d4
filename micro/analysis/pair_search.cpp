#include "micro/analysis/pair_search.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/errors.h"
#include "micro/geometry/neighbour_list.h"

namespace softglass::micro {

void for_each_pair_within(const LeesEdwardsBox& box, std::span<const Vec3> x,
                          std::span<const double> radius, double r_max,
                          const std::function<void(std::size_t, std::size_t, const Vec3&)>& visit) {
  require(r_max > 0.0 && r_max < 0.5 * box.side(),
          fmt::format("pair distance {} must be below half the cell side {}", r_max, 0.5 * box.side()));
  const double r2_max = r_max * r_max;
  const double max_radius = radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
  // The list holds pairs closer than R_i + R_j + skin; skin = r_max covers r_max.
  if (box.side() >= 3.0 * (2.0 * max_radius + r_max)) {
    NeighbourList list(r_max);
    list.build(box, x, radius);
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (const std::uint32_t entry : list.neighbours(i)) {
        const std::size_t j = NeighbourList::index(entry);
        const Vec3 d = box.minimum_image(x[i] - x[j]);
        if (d.squaredNorm() < r2_max) visit(i, j, d);
      }
    }
    return;
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      const Vec3 d = box.minimum_image(x[i] - x[j]);
      if (d.squaredNorm() < r2_max) visit(i, j, d);
    }
  }
}

}  // namespace softglass::micro
