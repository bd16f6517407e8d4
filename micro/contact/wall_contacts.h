// Particles against smooth flat walls: the wall as a sphere of infinite radius.
//
// Two walls y = y_lo and y = y_hi (normal e_y) bound the particles inside a
// Lees–Edwards cell (docs/physics.md, "Wall slip"). A particle α of radius R_α
// meets the lower wall with the signed distance d = y_α − y_lo of its centre
// (d = y_hi − y_α for the upper one), overlap h = R_α − d, and with R_β → ∞
// the pair's reduced radius R_α R_β/(R_α + R_β) → R_α:
//     R_c = R_α,   ε = h/R_α,   f = R_α² F(ε) n,   n = +e_y (lower), −e_y (upper),
// energy R_α³ W(ε), normal stiffness df/dh = R_α F'(ε): the same contact-law
// object as between particles. The wall is a half-space (the distance is
// signed): a particle pushed past the wall plane is pushed back, never
// through. Its Hessian block is k_n e_y e_y only: the tangential "prestress"
// term |f|/r of a pair vanishes with the wall's infinite radius, and the
// elastic wall force has no x component — a smooth wall takes shear only
// through the films (model/ehd_drag.h).
//
// The construction inside the periodic cell: an empty slab between y_hi and
// y_lo + L, at least 2(R_max + skin) wide, so that no particle reaches across
// the periodic y boundary (neither a contact nor a neighbour-list entry), and
// the Lees–Edwards offset never matters. Each wall moves with the affine flow
// at its own height, u_w = c y_w e_x; the walls thus impose the apparent rate
// (u_hi − u_lo)/(y_hi − y_lo) = c.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

class ContactLaw;
struct ContactField;
struct ForceRequest;

/// The heights of the two walls (units of R); none when lower == upper == 0.
struct Walls {
  double lower = 0.0, upper = 0.0;

  bool present() const { return upper > lower; }
  double gap() const { return upper - lower; }
  /// Checks the walls inside a cell of side `side` for particles of radii up
  /// to `max_radius` and a neighbour skin `skin`: 0 < lower < upper < side and
  /// an empty slab of at least 2(max_radius + skin) across the periodic
  /// boundary. InputError naming the walls otherwise.
  void check_inside(double side, double max_radius, double skin) const;
};

/// The wall contacts of a configuration (one entry per particle and wall it
/// touches).
struct WallContacts {
  std::vector<std::uint32_t> particle;
  std::vector<double> normal_y;        // n·e_y: +1 at the lower wall, −1 at the upper
  std::vector<double> distance;        // d = (y_α − y_w) n_y, signed: < 0 past the wall plane
  std::vector<double> deformation;     // ε = h/R_α
  std::vector<double> contact_radius;  // R_c = R_α
  std::vector<double> force;           // |f| = R_α² F(ε), along the wall's normal
  std::vector<double> stiffness;       // df/dh = R_α F'(ε)

  std::size_t size() const { return particle.size(); }
  bool empty() const { return particle.empty(); }
  void clear();
  /// The separation x_α − (x_α, y_w, z_α) of contact k: a pair's d with the
  /// wall's point of contact as the partner.
  Vec3 separation(std::size_t k) const { return Vec3(0.0, distance[k] * normal_y[k], 0.0); }
};

/// Finds the wall contacts of positions `x` (radii `radius`) and adds their
/// forces to out.force, their stiffness to out.stiffness_sum and, if
/// requested, their energy to out.energy; fills out.walls. The pair virial is
/// left alone: the walls are external bodies (wall stresses are measured by
/// the wall scene, analysis/wall_stress.h).
void add_wall_forces(const ContactLaw& law, const Walls& walls, std::span<const Vec3> x,
                     std::span<const double> radius, const ForceRequest& request,
                     ContactField& out);

}  // namespace softglass::micro
