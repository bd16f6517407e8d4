#include "micro/model/ehd_drag.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "common/errors.h"

namespace softglass::micro {

namespace {
constexpr std::size_t kParallelContacts = 8192;
constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 50;

inline double drag_coefficient(const ContactList& c, std::size_t k, double gamma_tilde) {
  return film_coefficient(gamma_tilde, c.contact_radius[k], c.force[k], c.deformation[k]);
}
// The film law of contact k (film.h) with coefficient `a`.
inline FilmLaw film_law(const ContactList& c, std::size_t k, double gamma_tilde, double a,
                        double rest_thickness) {
  return {a, film_crossover(rest_thickness, gamma_tilde, a, c.contact_radius[k], c.deformation[k])};
}
// The whole relative velocity q⁰ = v_i − v_j + c d_y e_x of a contact with
// non-affine part q at shear rate c: what the Stokes pair dashpots act on.
inline Vec3 relative_velocity(const Vec3& q, const Vec3& d, double rate) {
  return Vec3(q.x() + rate * d.y(), q.y(), q.z());
}
}  // namespace

DragCoupling parse_drag_coupling(const std::string& name) {
  if (name == "implicit") return DragCoupling::implicit;
  if (name == "lagged") return DragCoupling::lagged;
  throw InputError(fmt::format("drag coupling '{}' is unknown; allowed: implicit, lagged", name));
}

std::string to_string(DragCoupling coupling) {
  return coupling == DragCoupling::implicit ? "implicit" : "lagged";
}

void EhdSettings::validate() const {
  require(coupling == DragCoupling::implicit || !stokes.has_pairs(),
          "drag coupling 'lagged' is for the EHD drag alone: the Stokes friction against the "
          "neighbours needs 'implicit'");
  require(stokes.reservoir_share > 0.0 && stokes.reservoir_share <= 1.0,
          fmt::format("Stokes reservoir share = {} is outside (0, 1]", stokes.reservoir_share));
  require(std::isfinite(rest_thickness) && rest_thickness >= 0.0 && rest_thickness <= 0.5,
          fmt::format("film rest thickness = {} is outside [0, 0.5] (units of R)", rest_thickness));
  require(tolerance > 0.0 && tolerance < 1e-2,
          fmt::format("velocity solve tolerance = {} is outside (0, 1e-2)", tolerance));
  require(max_newton_iterations >= 1, "velocity solve needs at least one Newton iteration");
  require(max_cg_iterations >= 1, "velocity solve needs at least one CG iteration");
}

const WallContacts EhdDrag::kNoWalls{};

EhdDrag::EhdDrag(EhdSettings settings) : settings_(settings) {
  settings_.validate();
}

void EhdDrag::prepare(const ContactList& c, double gamma_tilde, double rate,
                      std::span<const double> friction) {
  const std::size_t m = c.size();
  rate_ = rate;
  geometry_.normal.resize(m);
  geometry_.coefficient.resize(m);
  geometry_.crossover.resize(m);
  geometry_.affine.resize(m);
  settings_.stokes.pair_coefficients(c, friction, geometry_.dashpot);
  reservoir_.resize(friction.size());
  for (std::size_t a = 0; a < friction.size(); ++a)
    reservoir_[a] = settings_.stokes.reservoir(friction[a]);
  const bool ehd = settings_.enabled;
  w_.resize(m);
  scratch_.resize(m);
#pragma omp parallel for schedule(static) if (m >= kParallelContacts)
  for (std::size_t k = 0; k < m; ++k) {
    geometry_.normal[k] = c.separation[k].normalized();
    geometry_.coefficient[k] = ehd ? drag_coefficient(c, k, gamma_tilde) : 0.0;
    geometry_.crossover[k] =
        film_law(c, k, gamma_tilde, geometry_.coefficient[k], settings_.rest_thickness).crossover;
    geometry_.affine[k] = settings_.film.affine(geometry_.normal[k], c.separation[k], rate);
  }
}

void EhdDrag::build_incidence(const ContactList& c, std::size_t n) {
  incidence_start_.assign(n + 1, 0);
  for (std::size_t k = 0; k < c.size(); ++k) {
    ++incidence_start_[c.i[k] + 1];
    ++incidence_start_[c.j[k] + 1];
  }
  for (std::size_t a = 0; a < n; ++a) incidence_start_[a + 1] += incidence_start_[a];
  incidence_.resize(2 * c.size());
  std::vector<std::size_t> fill(incidence_start_.begin(), incidence_start_.end() - 1);
  for (std::size_t k = 0; k < c.size(); ++k) {
    incidence_[fill[c.i[k]]++] = static_cast<std::uint32_t>(2 * k);
    incidence_[fill[c.j[k]]++] = static_cast<std::uint32_t>(2 * k + 1);
  }
}

void EhdDrag::gather(std::span<const Vec3> per_contact, std::span<Vec3> out) const {
  const std::size_t n = out.size();
#pragma omp parallel for schedule(static) if (n >= kParallelContacts)
  for (std::size_t a = 0; a < n; ++a) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t e = incidence_start_[a]; e < incidence_start_[a + 1]; ++e) {
      const std::uint32_t code = incidence_[e];
      if (code & 1u)
        sum -= per_contact[code >> 1];
      else
        sum += per_contact[code >> 1];
    }
    out[a] += sum;
  }
}

void EhdDrag::gradient_at(const ContactList& c, std::span<const Vec3> force,
                          std::span<const Vec3> v, std::vector<Vec3>& w,
                          std::vector<Vec3>& gradient, bool trial) {
  const std::size_t m = c.size();
#pragma omp parallel for schedule(static) if (m >= kParallelContacts)
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 q = v[c.i[k]] - v[c.j[k]];
    w[k] = settings_.film.project(geometry_.normal[k], q) + geometry_.affine[k];
    // ∂/∂w of the film potential = s(|w|) w (film.h: a w/|w|^{1/2} on the EHD
    // branch); of ½ b |q⁰|², b q⁰
    const double secant =
        FilmLaw{geometry_.coefficient[k], geometry_.crossover[k]}.secant(w[k].norm());
    scratch_[k] =
        w[k] * secant + geometry_.dashpot[k] * relative_velocity(q, c.separation[k], rate_);
    secant_[k] = secant;
  }
  for (std::size_t a = 0; a < v.size(); ++a) gradient[a] = reservoir_[a] * v[a] - force[a];
  gather(scratch_, gradient);
  walls_.add_gradient(v, trial, gradient);
}

int EhdDrag::newton_direction(const ContactList& c, std::span<const double> friction,
                              double velocity_scale, double eta) {
  const std::size_t n = friction.size(), m = c.size();
  // Hessian data at the current point and the 3×3 diagonal blocks. Below the
  // |w| at which a contact's drag a√|w| falls under the force tolerance
  // (tol · scale · ζ), its exact value does not matter: the model's |w| is
  // floored there, which bounds the curvature.
  for (std::size_t a = 0; a < n; ++a)
    block_inverse_[a] = reservoir_[a] * Eigen::Matrix3d::Identity();
  for (std::size_t k = 0; k < m; ++k) {
    const double speed = w_[k].norm();
    const double resolution = settings_.tolerance * velocity_scale *
                              std::min(friction[c.i[k]], friction[c.j[k]]) /
                              geometry_.coefficient[k];
    const FilmLaw law{geometry_.coefficient[k], geometry_.crossover[k]};
    s_[k] = law.secant(std::max(speed, resolution * resolution));
    // A film in its linear regime has the isotropic curvature s P: no relief.
    unit_w_[k] = speed > 0.0 && !law.linear(speed) ? Vec3(w_[k] / speed) : Vec3::Zero();
    const Eigen::Matrix3d block = s_[k] * (settings_.film.projector(geometry_.normal[k]) -
                                           relief_[k] * unit_w_[k] * unit_w_[k].transpose()) +
                                  geometry_.dashpot[k] * Eigen::Matrix3d::Identity();
    block_inverse_[c.i[k]] += block;
    block_inverse_[c.j[k]] += block;
  }
  walls_.add_blocks(settings_.tolerance * velocity_scale, friction, block_inverse_);
  for (auto& b : block_inverse_) b = b.inverse().eval();

  // H p = ζ p + Σ_c ±A_c (p_i − p_j),  A_c q = s_c (P q − θ_c ŵ(ŵ·q)) + b_c q.
  const auto hessian_times = [&](const std::vector<Vec3>& in, std::vector<Vec3>& out) {
#pragma omp parallel for schedule(static) if (m >= kParallelContacts)
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3 q = in[c.i[k]] - in[c.j[k]];
      scratch_[k] = s_[k] * (settings_.film.project(geometry_.normal[k], q) -
                             relief_[k] * unit_w_[k] * unit_w_[k].dot(q)) +
                    geometry_.dashpot[k] * q;
    }
    for (std::size_t a = 0; a < n; ++a) out[a] = reservoir_[a] * in[a];
    gather(scratch_, out);
    walls_.add_hessian_times(in, out);
  };

  // The drag Hessian is positive definite (ζ > 0): no truncation needed. A
  // uniform translation meets only the reservoir friction.
  double translation_stiffness = 0.0;
  for (const double zeta : reservoir_) translation_stiffness += zeta;
  return solve_newton_system(
             gradient_, hessian_times,
             [&](std::size_t a, const Vec3& r) -> Vec3 { return block_inverse_[a] * r; },
             translation_stiffness, eta, settings_.max_cg_iterations, false, step_, cg_)
      .iterations;
}

EhdDrag::Change EhdDrag::change_along_step(const ContactList& c, std::span<const Vec3> force,
                                           std::span<const Vec3> v, double t) {
  const std::size_t n = v.size(), m = c.size();
  double change = 0.0, magnitude = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    trial_[a] = v[a] + t * step_[a];
    const double quadratic =
        t * reservoir_[a] * (v[a].dot(step_[a]) + 0.5 * t * step_[a].squaredNorm());
    const double linear = t * force[a].dot(step_[a]);
    change += quadratic - linear;
    magnitude += std::abs(quadratic) + std::abs(linear);
  }
  // The trial point's drag terms, its tangential velocities and gradient (kept
  // for when the step is accepted).
#pragma omp parallel for schedule(static) reduction(+ : change, magnitude) if (m >= kParallelContacts)
  for (std::size_t k = 0; k < m; ++k) {
    w_trial_[k] = settings_.film.project(geometry_.normal[k], trial_[c.i[k]] - trial_[c.j[k]]) +
                  geometry_.affine[k];
    const double speed = w_trial_[k].norm();
    const FilmLaw law{geometry_.coefficient[k], geometry_.crossover[k]};
    const FilmLaw::Change film = law.change(w_[k].norm(), speed);
    change += film.value;
    magnitude += film.magnitude;
    scratch_[k] = w_trial_[k] * law.secant(speed);
    // ½ b |q⁰|² changes by b (t q⁰·δq + ½ t² |δq|²) along the step δq
    if (const double b = geometry_.dashpot[k]; b > 0.0) {
      const Vec3 q0 = relative_velocity(v[c.i[k]] - v[c.j[k]], c.separation[k], rate_);
      const Vec3 dq = step_[c.i[k]] - step_[c.j[k]];
      const double pair = b * t * (q0.dot(dq) + 0.5 * t * dq.squaredNorm());
      change += pair;
      magnitude += std::abs(pair);
      scratch_[k] += b * (q0 + t * dq);
    }
  }
  for (std::size_t a = 0; a < n; ++a) gradient_trial_[a] = reservoir_[a] * trial_[a] - force[a];
  gather(scratch_, gradient_trial_);
  const FilmLaw::Change walls = walls_.change_to(trial_, gradient_trial_);
  change += walls.value;
  magnitude += walls.magnitude;
  // Each term carries a relative rounding error of a few ε; 64ε of their
  // magnitudes bounds the error of the sum with a margin.
  return {change, 64.0 * std::numeric_limits<double>::epsilon() * magnitude};
}

VelocitySolveStats EhdDrag::solve(const ContactList& c, double gamma_tilde, double rate,
                                  std::span<const double> friction, std::span<const Vec3> force,
                                  std::span<Vec3> v, const WallContacts& walls) {
  const std::size_t n = v.size();
  const std::size_t m = c.size();
  prepare(c, gamma_tilde, rate, friction);
  walls_.prepare(walls, settings_.film, settings_.enabled, gamma_tilde, rate,
                 settings_.rest_thickness);
  build_incidence(c, n);
  for (auto* vec : {&w_trial_, &unit_w_}) vec->resize(m);
  secant_.resize(m);
  for (auto* vec : {&gradient_, &gradient_trial_, &trial_, &step_}) vec->resize(n);
  block_inverse_.resize(n);
  s_.resize(m);
  VelocitySolveStats stats;

  gradient_at(c, force, v, w_, gradient_, false);
  if (settings_.coupling == DragCoupling::lagged) {
    // One sweep with the drag of the previous velocities: ζ v = F^e + F^EHD(v_prev).
    for (std::size_t a = 0; a < n; ++a) v[a] -= gradient_[a] / reservoir_[a];
    stats.newton_iterations = 1;
    return stats;
  }
  Residual r = relative_residual(gradient_, v, friction);
  stats.fixed_point_sweeps = jacobi_sweeps(c, friction, force, v, r);
  newton(c, friction, force, v, r, stats);
  return stats;
}

EhdDrag::Residual EhdDrag::relative_residual(const std::vector<Vec3>& gradient,
                                             std::span<const Vec3> at,
                                             std::span<const double> friction) const {
  double residual = 0.0, scale = 1.0;
  for (std::size_t a = 0; a < at.size(); ++a) {
    residual = std::max(residual, gradient[a].norm() / friction[a]);
    scale = std::max(scale, at[a].norm());
  }
  return {residual / scale, scale};
}

// Fixed-point sweeps while each at least halves the residual: one contact pass
// each, and when the drag is weaker than the friction (γ̃ ≳ 1e-6) a few suffice
// (see the header). Nonlinear Jacobi: each particle's own stiffness, friction
// plus ¾ of the secant stiffness a/√|w| of its contacts' drag (the drag's
// curvature is ½ of it along the slip and all of it across; ¾ measured best:
// 4.3 sweeps per evaluation at γ̃ = 1e-4 against 6.3 with the friction alone),
// plus the Stokes pair dashpots.
int EhdDrag::jacobi_sweeps(const ContactList& c, std::span<const double> friction,
                           std::span<const Vec3> force, std::span<Vec3> v, Residual& r) {
  int sweeps = 0;
  while (r.residual > settings_.tolerance) {
    if (walls_.size() > 0) {
      wall_secant_.assign(v.size(), 0.0);
      walls_.add_secants(wall_secant_);
    }
    for (std::size_t a = 0; a < v.size(); ++a) {
      double local = 0.0, pairs = 0.0;
      for (std::size_t e = incidence_start_[a]; e < incidence_start_[a + 1]; ++e) {
        local += secant_[incidence_[e] >> 1];
        pairs += geometry_.dashpot[incidence_[e] >> 1];
      }
      if (walls_.size() > 0) local += wall_secant_[a];
      trial_[a] = v[a] - gradient_[a] / (reservoir_[a] + 0.75 * local + pairs);
    }
    gradient_at(c, force, trial_, w_trial_, gradient_trial_, true);
    const Residual trial = relative_residual(gradient_trial_, trial_, friction);
    if (trial.residual > 0.5 * r.residual) break;
    std::copy(trial_.begin(), trial_.end(), v.begin());
    w_.swap(w_trial_);
    walls_.accept_trial();
    gradient_.swap(gradient_trial_);
    r = trial;
    ++sweeps;
  }
  return sweeps;
}

// Newton. Curvature of each contact's drag term along ŵ: exact (θ = ½) to
// start with (the solve is warm-started), the majoriser (θ = 0) while the
// contact's |w| shrinks fast; see the header.
void EhdDrag::newton(const ContactList& c, std::span<const double> friction,
                     std::span<const Vec3> force, std::span<Vec3> v, Residual r,
                     VelocitySolveStats& stats) {
  relief_.assign(c.size(), 0.0);
  walls_.reset_relief();
  double first_norm = 0.0;
  for (int it = 0;; ++it) {
    if (it > 0) r = relative_residual(gradient_, v, friction);
    stats.residual = r.residual;
    if (stats.residual <= settings_.tolerance) return;
    if (it == settings_.max_newton_iterations) {
      throw NumericalError(fmt::format(
          "EHD velocity solve did not converge in {} Newton iterations (residual {:.3g}, "
          "tolerance {:.3g})",
          it, stats.residual, settings_.tolerance));
    }
    ++stats.newton_iterations;

    // Inexact Newton: forcing term η → 0 as the gradient falls (superlinear).
    const double gnorm = std::sqrt(dot(gradient_, gradient_));
    if (it == 0) first_norm = gnorm;
    stats.cg_iterations +=
        newton_direction(c, friction, r.scale, std::min(1e-3, std::sqrt(gnorm / first_norm)));
    line_search(c, force, v, gnorm);
    // The majoriser for contacts whose |w| shrinks fast, and for every shrinking
    // contact when the iteration made poor progress (a crawl).
    const double progress =
        relative_residual(gradient_trial_, trial_, friction).residual / r.residual;
    const double keep = progress > 0.5 ? 1.0 : 0.9;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const double before = w_[k].norm(), after = w_trial_[k].norm();
      relief_[k] = after >= keep * before ? 0.5 : 0.0;
    }
    walls_.update_relief(keep);
    std::copy(trial_.begin(), trial_.end(), v.begin());
    w_.swap(w_trial_);
    walls_.accept_trial();
    gradient_.swap(gradient_trial_);
  }
}

// Backtracking line search (Armijo) on the change of Φ along the step, computed
// term by term: the friction and force terms exactly, the drag contact by
// contact. Φ itself is dominated by −F·v + ½ζ|v|², far larger than the changes
// that matter, so comparing values of Φ would lose them. Near the solution at
// low γ̃ the decrease can drop below that computation's rounding (the friction
// ζ ∝ γ̃ makes the slope g·δ tiny); then the step is judged by the gradient,
// which keeps its precision. Leaves the trial point in the trial buffers.
void EhdDrag::line_search(const ContactList& c, std::span<const Vec3> force,
                          std::span<const Vec3> v, double gnorm) {
  const double slope = dot(gradient_, step_);
  double t = 1.0;
  for (int halvings = 0; halvings < kMaxHalvings; ++halvings, t *= 0.5) {
    const Change change = change_along_step(c, force, v, t);
    if (change.value <= kArmijo * t * slope) break;
    if (std::abs(change.value) <= change.rounding &&
        dot(gradient_trial_, gradient_trial_) < gnorm * gnorm)
      break;
  }
}

DissipativeVirial EhdDrag::virial(const ContactList& c, double gamma_tilde, double rate,
                                  std::span<const Vec3> v, std::span<Vec3> drag,
                                  std::span<const double> friction,
                                  std::span<Vec3> per_contact) const {
  std::vector<double> dashpot;
  if (settings_.stokes.has_pairs()) {
    if (friction.size() != v.size())
      throw std::invalid_argument("EhdDrag::virial: the Stokes pair dashpots need the frictions");
    settings_.stokes.pair_coefficients(c, friction, dashpot);
  }
  DissipativeVirial sum;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3 q = v[c.i[k]] - v[c.j[k]];
    const Vec3 w = settings_.film.sliding(c.separation[k].normalized(), q, c.separation[k], rate);
    Vec3 film = Vec3::Zero(), dashpot_force = Vec3::Zero();  // on i from j
    if (settings_.enabled) {
      const FilmLaw law = film_law(c, k, gamma_tilde, drag_coefficient(c, k, gamma_tilde),
                                   settings_.rest_thickness);
      film = -law.secant(w.norm()) * w;
    }
    sum.film += c.separation[k] * film.transpose();
    if (!dashpot.empty()) {
      dashpot_force = -dashpot[k] * relative_velocity(q, c.separation[k], rate);
      sum.friction += c.separation[k] * dashpot_force.transpose();
    }
    const Vec3 f = film + dashpot_force;
    if (!per_contact.empty()) per_contact[k] = f;
    if (!drag.empty()) {
      drag[c.i[k]] += f;
      drag[c.j[k]] -= f;
    }
  }
  return sum;
}

}  // namespace softglass::micro

namespace softglass::micro {

void EhdDrag::wall_drag(const WallContacts& walls, double gamma_tilde, double rate,
                        std::span<const Vec3> v, std::span<Vec3> per_film,
                        std::span<Vec3> drag) const {
  WallFilms films;
  films.prepare(walls, settings_.film, settings_.enabled, gamma_tilde, rate,
                settings_.rest_thickness);
  films.forces(v, per_film, drag);
}

}  // namespace softglass::micro
