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
//
// A film of finite rest thickness (`film rest thickness` h0, units of R; 0,
// the default, is the paper's law). The EHD law implies a film thickness
// δ = η_s u A/f with the facet's area A = π ε R_c² (a Couette film of area A
// carrying the drag f): in reduced units δ = π γ̃ ε R_c² |w|^{1/2}/a_c, which
// vanishes as the sliding stops, where its drag's viscosity a_c/|w|^{1/2}
// diverges. A real film keeps a thickness h0 set by the surfactant's
// disjoining pressure, and drags linearly, η_s u A/h0, below the speed w* at
// which δ falls to h0:
//     w* = (h0 a_c / (π γ̃ ε R_c²))²,   f = a_c |w|/√w* for |w| < w*.
// The drag is continuous at w*, and its potential — ½ (a_c/√w*) |w|² below,
// ⅔ a_c |w|^{3/2} − ⅙ a_c w*^{3/2} above — stays convex (C¹). Both regimes
// are f = s(|w|) w with the secant s = a_c/√max(|w|, w*) (FilmLaw below). A
// declared extension of the paper's model: docs/physics.md, docs/oscillation.md.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
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

/// w* of a contact with coefficient a_c, radius R_c and deformation ε, for a
/// film of rest thickness h0 (units of R; 0: none, w* = 0).
inline double film_crossover(double rest_thickness, double gamma_tilde, double coefficient,
                             double contact_radius, double deformation) {
  if (!(rest_thickness > 0.0) || !(coefficient > 0.0)) return 0.0;
  const double root =
      rest_thickness * coefficient /
      (std::numbers::pi * gamma_tilde * deformation * contact_radius * contact_radius);
  return root * root;
}

/// One film's drag against its sliding speed (see the header): the secant
/// s = |f|/|w|, the potential and whether it is in the linear regime.
struct FilmLaw {
  double coefficient;  // a_c
  double crossover;    // w* (0: the paper's √|w| law at every speed)

  double secant(double speed) const {
    const double at = std::max(speed, crossover);
    return at > 0.0 ? coefficient / std::sqrt(at) : 0.0;
  }
  bool linear(double speed) const { return speed < crossover; }
  double potential(double speed) const {
    if (linear(speed)) return 0.5 * secant(speed) * speed * speed;
    // Without a rest thickness the second term is exactly 0: the paper's ⅔ a |w|^{3/2}.
    return (2.0 / 3.0) * coefficient * speed * std::sqrt(speed) -
           (1.0 / 6.0) * coefficient * crossover * std::sqrt(crossover);
  }
  /// The potential's change from speed `before` to `after`, and the sum of
  /// the magnitudes it was computed from (its rounding scale); on the EHD
  /// branch as ⅔ a (after^{3/2} − before^{3/2}), without the constant.
  struct Change {
    double value, magnitude;
  };
  Change change(double before, double after) const {
    if (linear(before) || linear(after)) {
      const double a = potential(after), b = potential(before);
      return {a - b, std::abs(a) + std::abs(b)};
    }
    const double now = after * std::sqrt(after), then = before * std::sqrt(before);
    return {(2.0 / 3.0) * coefficient * (now - then), (2.0 / 3.0) * coefficient * (now + then)};
  }
};

/// Many films' speeds, secants and potentials at once: on entry `speed`
/// holds |w|², on return |w|; `secant` and `potential` are FilmLaw's at |w|,
/// to the last bit, for films with `coefficient` a_c and `crossover` w*.
/// Compiled so that FilmLaw's regimes become selects (micro/CMakeLists.txt)
/// and the square roots and divisions of several films go in one instruction;
/// film by film, the branch on the regime (a film near w* goes either way) and
/// the square root whose result it waits for bounded the implicit step's
/// evaluation of Φ.
void evaluate_films(std::span<const double> coefficient, std::span<const double> crossover,
                    std::span<double> speed, std::span<double> secant,
                    std::span<double> potential);

struct FilmModel {
  FilmVelocity velocity = FilmVelocity::tangential;

  /// P q for the contact normal n.
  Vec3 project(const Vec3& n, const Vec3& q) const {
    return velocity == FilmVelocity::full ? q : Vec3(q - n * n.dot(q));
  }
  /// P as a matrix, written entry by entry: as the expression I − n nᵀ, it went
  /// through the stack in halves and whole packets, and the Hessian assemblies
  /// that call it once per contact stalled on reloading it.
  Eigen::Matrix3d projector(const Vec3& n) const {
    Eigen::Matrix3d p;
    const bool tangential = velocity != FilmVelocity::full;
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row)
        p(row, col) = (row == col ? 1.0 : 0.0) - (tangential ? n[row] * n[col] : 0.0);
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
