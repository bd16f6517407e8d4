// The lubricating films between particles and smooth walls: the one-body
// terms of the EHD velocity solve (ehd_drag.h).
//
// A wall contact (contact/wall_contacts.h) is a pair contact whose partner is
// a sphere of infinite radius moving with the affine flow at the wall's
// height, u_w = c y_w e_x. Its film is the pair film's law with R_c = R_α
// (film.h): coefficient a = (¾ γ̃ R_α |f| √ε)^{1/2}, the same rest thickness,
// the same projection P (normal n = ±e_y), acting on the particle's velocity
// relative to the wall,
//     w = P(v_α + c (y_α − y_w) e_x) = P v_α + w⁰,
// which is exactly a pair's w with v_β = 0 (the wall's non-affine velocity)
// and d = x_α − (x_α, y_w, z_α). The velocity solve's convex function Φ gains
// the one-body terms ⅔ a |w|^{3/2} (film potential), whose gradient s(|w|) w
// and curvature s (P − θ ŵŵᵀ) enter only particle α's rows: the same
// majoriser/Newton machinery, one more loop per pass.
//
// No Stokes pair dashpot acts between a particle and a wall: the dashpots
// share a particle's own friction among its particle neighbours
// (stokes_friction.h), and the wall has none to share.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "micro/contact/wall_contacts.h"
#include "micro/model/film.h"

namespace softglass::micro {

class WallFilms {
 public:
  /// The films of `walls` at rate c; `enabled` false leaves them without drag.
  void prepare(const WallContacts& walls, const FilmModel& film, bool enabled, double gamma_tilde,
               double rate, double rest_thickness);
  std::size_t size() const { return particle_.size(); }

  /// Adds s(|w|) w of every film to `gradient` at velocities v, leaving the
  /// films' w in `w` (the current or the trial buffer) and their secants.
  void add_gradient(std::span<const Vec3> v, bool trial, std::span<Vec3> gradient);
  /// Adds each film's secant s(|w|) at the last gradient to its particle's.
  void add_secants(std::span<double> per_particle) const;
  /// The Hessian model at the current w: adds each film's block
  /// s (P − θ ŵŵᵀ) to its particle's; |w| is floored where a film's drag falls
  /// below `force_scale` × its particle's friction ζ (as for pairs, ehd_drag.h).
  void add_blocks(double force_scale, std::span<const double> friction,
                  std::span<Eigen::Matrix3d> blocks);
  /// out_α += the model's curvature applied to `in`.
  void add_hessian_times(std::span<const Vec3> in, std::span<Vec3> out) const;
  /// The films' potential change from the current w to v + t δ (filling the
  /// trial w) and its rounding scale; adds their gradient there to
  /// `trial_gradient`.
  FilmLaw::Change change_to(std::span<const Vec3> trial_point, std::span<Vec3> trial_gradient);
  /// θ = ½ (Newton) unless the film's |w| shrank below `keep` × its value.
  void update_relief(double keep);
  /// The trial point became the current one.
  void accept_trial() { w_.swap(w_trial_); }
  void reset_relief() { relief_.assign(size(), 0.0); }

  /// Each film's drag on its particle at velocities v, and their sum in
  /// `drag` if not empty (per particle).
  void forces(std::span<const Vec3> v, std::span<Vec3> per_film, std::span<Vec3> drag) const;

 private:
  FilmLaw law(std::size_t k) const { return {coefficient_[k], crossover_[k]}; }

  FilmModel film_{};
  std::vector<std::uint32_t> particle_;
  std::vector<Vec3> normal_, affine_, w_, w_trial_, unit_w_;
  std::vector<double> coefficient_, crossover_, secant_, s_, relief_;
};

}  // namespace softglass::micro
