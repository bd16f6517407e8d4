// The lubricating film of a contact: the EHD drag's coefficient, and which
// relative velocity of the two particles it acts on.
//
// The drag on α from β is f = −a_c |w|^{1/2} ŵ (reduced units, ehd_drag.h),
//     a_c = (γ̃ C R_c³ ε^{(2n+1)/2})^{1/2} = (¾ γ̃ R_c |f^e| √ε)^{1/2},
// the second form because C ε^n = ¾ F(ε) for every contact law. The velocity w
// is a projection of the relative velocity q = v_α − v_β + u∞_α − u∞_β, where v
// is the non-affine velocity and u∞_α − u∞_β = c d_y e_x the affine one, c the
// shear rate in units of the run's reference rate (1 in steady shear;
// shear_drive.h):
//
//   `tangential` (the paper)  w = (I − n nᵀ) q: the film resists sliding of the
//                             facets only; approach and separation are free.
//   `full`                    w = q: the same law for every direction of the
//                             relative motion (a declared extension: the film
//                             also resists the normal motion, with the sliding
//                             drag's magnitude; docs/physics.md).
//   `nonaffine`               w = (I − n nᵀ)(v_α − v_β): sliding relative to
//                             the affine flow only (a diagnostic variant).
//
// Every variant is w = P q⁰ + P(v_α − v_β) with a constant projector P (per
// contact) and an affine part w⁰ = P(c d_y e_x) or 0; the drag potential
// ⅔ a_c |w|^{3/2} then stays convex in v, which the velocity solve and the
// implicit integrator rely on.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

enum class FilmVelocity { tangential, full, nonaffine };
FilmVelocity parse_film_velocity(const std::string& name);
std::string to_string(FilmVelocity velocity);
/// "tangential|full|nonaffine", for the parameter file.
std::string film_velocity_names();

/// a_c for a contact of radius R_c, force |f| (units E* R²) and deformation ε.
inline double film_coefficient(double gamma_tilde, double contact_radius, double force,
                               double deformation) {
  return std::sqrt(0.75 * gamma_tilde * contact_radius * force * std::sqrt(deformation));
}

struct FilmModel {
  FilmVelocity velocity = FilmVelocity::tangential;

  /// P q for the contact normal n.
  Vec3 project(const Vec3& n, const Vec3& q) const {
    return velocity == FilmVelocity::full ? q : Vec3(q - n * n.dot(q));
  }
  /// P as a matrix.
  Eigen::Matrix3d projector(const Vec3& n) const {
    Eigen::Matrix3d p = Eigen::Matrix3d::Identity();
    if (velocity != FilmVelocity::full) p -= n * n.transpose();
    return p;
  }
  /// w⁰ = P(c d_y e_x) for the separation d at shear rate c (zero for `nonaffine`).
  Vec3 affine(const Vec3& n, const Vec3& d, double rate) const {
    if (velocity == FilmVelocity::nonaffine) return Vec3::Zero();
    return project(n, Vec3(rate * d.y(), 0.0, 0.0));
  }
  /// w = P(v_α − v_β) + w⁰ for the non-affine relative velocity dv.
  Vec3 sliding(const Vec3& n, const Vec3& dv, const Vec3& d, double rate) const {
    return project(n, dv) + affine(n, d, rate);
  }
};

}  // namespace softglass::micro
