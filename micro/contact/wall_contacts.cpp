#include "micro/contact/wall_contacts.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"
#include "micro/contact/contact_forces.h"
#include "micro/contact/contact_law.h"

namespace softglass::micro {

void Walls::check_inside(double side, double max_radius, double skin) const {
  require(std::isfinite(lower) && std::isfinite(upper) && lower > 0.0 && upper > lower &&
              upper < side,
          fmt::format("walls: y_lo = {} and y_hi = {} must satisfy 0 < y_lo < y_hi < L = {}",
                      lower, upper, side));
  const double slab = side - upper + lower, needed = 2.0 * (max_radius + skin);
  require(slab >= needed,
          fmt::format("walls: the empty slab across the periodic boundary, L − y_hi + y_lo = {:.4g} "
                      "R, is narrower than 2 (R_max + skin) = {:.4g} R: particles would reach "
                      "across it",
                      slab, needed));
}

void WallContacts::clear() {
  particle.clear();
  normal_y.clear();
  distance.clear();
  deformation.clear();
  contact_radius.clear();
  force.clear();
  stiffness.clear();
}

void add_wall_forces(const ContactLaw& law, const Walls& walls, std::span<const Vec3> x,
                     std::span<const double> radius, const ForceRequest& request,
                     ContactField& out) {
  WallContacts& c = out.walls;
  c.clear();
  const auto touch = [&](std::size_t a, double normal, double distance) {
    const double r = radius[a];
    const double h = r - distance;
    if (!(h > 0.0)) return;
    const double eps = h / r;
    const double f = r * r * law.force(eps);
    const double k = r * law.stiffness(eps);
    c.particle.push_back(static_cast<std::uint32_t>(a));
    c.normal_y.push_back(normal);
    c.distance.push_back(distance);
    c.deformation.push_back(eps);
    c.contact_radius.push_back(r);
    c.force.push_back(f);
    c.stiffness.push_back(k);
    out.force[a].y() += normal * f;
    out.stiffness_sum[a] += k;
    if (request.energy) out.energy += r * r * r * law.energy(eps);
  };
  // Each particle meets the wall on its side of mid-gap, at the signed
  // distance of its centre (negative past the plane: ε > 1 pushes it back).
  const double mid = 0.5 * (walls.lower + walls.upper);
  for (std::size_t a = 0; a < x.size(); ++a) {
    const double y = x[a].y();
    if (y < mid)
      touch(a, 1.0, y - walls.lower);
    else
      touch(a, -1.0, walls.upper - y);
  }
}

}  // namespace softglass::micro
