#include "micro/model/wall_films.h"

#include <algorithm>

namespace softglass::micro {

void WallFilms::prepare(const WallContacts& walls, const FilmModel& film, bool enabled,
                        double gamma_tilde, double rate, double rest_thickness) {
  const std::size_t m = walls.size();
  film_ = film;
  particle_.assign(walls.particle.begin(), walls.particle.end());
  normal_.resize(m);
  affine_.resize(m);
  coefficient_.resize(m);
  crossover_.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    normal_[k] = Vec3(0.0, walls.normal_y[k], 0.0);
    const double rc = walls.contact_radius[k], eps = walls.deformation[k];
    coefficient_[k] = enabled ? film_coefficient(gamma_tilde, rc, walls.force[k], eps) : 0.0;
    crossover_[k] = film_crossover(rest_thickness, gamma_tilde, coefficient_[k], rc, eps);
    affine_[k] = film.affine(normal_[k], walls.separation(k), rate);
  }
  for (auto* vec : {&w_, &w_trial_, &unit_w_}) vec->resize(m);
  for (auto* vec : {&secant_, &s_}) vec->resize(m);
  relief_.assign(m, 0.0);
}

void WallFilms::add_gradient(std::span<const Vec3> v, bool trial, std::span<Vec3> gradient) {
  std::vector<Vec3>& w = trial ? w_trial_ : w_;
  for (std::size_t k = 0; k < size(); ++k) {
    const std::uint32_t a = particle_[k];
    w[k] = film_.project(normal_[k], v[a]) + affine_[k];
    secant_[k] = law(k).secant(w[k].norm());
    gradient[a] += secant_[k] * w[k];
  }
}

void WallFilms::add_secants(std::span<double> per_particle) const {
  for (std::size_t k = 0; k < size(); ++k) per_particle[particle_[k]] += secant_[k];
}

void WallFilms::add_blocks(double force_scale, std::span<const double> friction,
                           std::span<Eigen::Matrix3d> blocks) {
  for (std::size_t k = 0; k < size(); ++k) {
    const std::uint32_t a = particle_[k];
    const double speed = w_[k].norm();
    const double resolution = force_scale * friction[a] / coefficient_[k];
    s_[k] = law(k).secant(std::max(speed, resolution * resolution));
    unit_w_[k] = speed > 0.0 && !law(k).linear(speed) ? Vec3(w_[k] / speed) : Vec3::Zero();
    blocks[a] += s_[k] * (film_.projector(normal_[k]) - relief_[k] * unit_w_[k] * unit_w_[k].transpose());
  }
}

void WallFilms::add_hessian_times(std::span<const Vec3> in, std::span<Vec3> out) const {
  for (std::size_t k = 0; k < size(); ++k) {
    const std::uint32_t a = particle_[k];
    out[a] += s_[k] * (film_.project(normal_[k], in[a]) - relief_[k] * unit_w_[k] * unit_w_[k].dot(in[a]));
  }
}

FilmLaw::Change WallFilms::change_to(std::span<const Vec3> trial_point,
                                     std::span<Vec3> trial_gradient) {
  FilmLaw::Change sum{0.0, 0.0};
  for (std::size_t k = 0; k < size(); ++k) {
    const std::uint32_t a = particle_[k];
    w_trial_[k] = film_.project(normal_[k], trial_point[a]) + affine_[k];
    const double speed = w_trial_[k].norm();
    const FilmLaw::Change c = law(k).change(w_[k].norm(), speed);
    sum.value += c.value;
    sum.magnitude += c.magnitude;
    trial_gradient[a] += law(k).secant(speed) * w_trial_[k];
  }
  return sum;
}

void WallFilms::update_relief(double keep) {
  for (std::size_t k = 0; k < size(); ++k)
    relief_[k] = w_trial_[k].norm() >= keep * w_[k].norm() ? 0.5 : 0.0;
}

void WallFilms::forces(std::span<const Vec3> v, std::span<Vec3> per_film,
                       std::span<Vec3> drag) const {
  for (std::size_t k = 0; k < size(); ++k) {
    const std::uint32_t a = particle_[k];
    const Vec3 w = film_.project(normal_[k], v[a]) + affine_[k];
    const Vec3 f = -law(k).secant(w.norm()) * w;
    if (!per_film.empty()) per_film[k] = f;
    if (!drag.empty()) drag[a] += f;
  }
}

}  // namespace softglass::micro
