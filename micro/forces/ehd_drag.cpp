#include "micro/forces/ehd_drag.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

#include "common/errors.h"

namespace softglass::micro {

namespace {
constexpr std::size_t kParallelContacts = 8192;
// Newton's Hessian uses |w| ≥ this fraction of the velocity scale (see header).
constexpr double kHessianFloor = 1e-6;
constexpr double kArmijo = 1e-4;

// a_c = (¾ γ̃ R_c |f| √ε)^{1/2}; see the header.
inline double drag_coefficient(const ContactList& c, std::size_t k, double gamma_tilde) {
  return std::sqrt(0.75 * gamma_tilde * c.contact_radius[k] * c.force[k] * std::sqrt(c.deformation[k]));
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
  require(tolerance > 0.0 && tolerance < 1e-2,
          fmt::format("velocity solve tolerance = {} is outside (0, 1e-2)", tolerance));
  require(max_newton_iterations >= 1, "velocity solve needs at least one Newton iteration");
  require(max_cg_iterations >= 1, "velocity solve needs at least one CG iteration");
}

EhdDrag::EhdDrag(EhdSettings settings) : settings_(settings) { settings_.validate(); }

void EhdDrag::prepare(const ContactList& c, double gamma_tilde) {
  const std::size_t m = c.size();
  geometry_.normal.resize(m);
  geometry_.coefficient.resize(m);
  w_.resize(m);
  scratch_.resize(m);
#pragma omp parallel for schedule(static) if (m >= kParallelContacts)
  for (std::size_t k = 0; k < m; ++k) {
    geometry_.normal[k] = c.separation[k].normalized();
    geometry_.coefficient[k] = drag_coefficient(c, k, gamma_tilde);
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
      if (code & 1u) sum -= per_contact[code >> 1];
      else sum += per_contact[code >> 1];
    }
    out[a] += sum;
  }
}

double EhdDrag::objective(const ContactList& c, std::span<const double> friction,
                          std::span<const Vec3> force, std::span<const Vec3> v,
                          std::vector<Vec3>& w, std::vector<Vec3>& gradient) {
  const std::size_t m = c.size();
  double phi = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : phi) if (m >= kParallelContacts)
  for (std::size_t k = 0; k < m; ++k) {
    Vec3 g = v[c.i[k]] - v[c.j[k]];
    g.x() += c.separation[k].y();  // affine relative velocity γ̇ d_y e_x (γ̇ = 1)
    const Vec3& n = geometry_.normal[k];
    w[k] = g - n * n.dot(g);
    const double speed = w[k].norm();
    const double root = std::sqrt(speed);
    const double a = geometry_.coefficient[k];
    phi += (2.0 / 3.0) * a * speed * root;
    // ∂/∂w of ⅔ a |w|^{3/2} = a |w|^{1/2} ŵ = a w / |w|^{1/2}
    scratch_[k] = speed > 0.0 ? Vec3(w[k] * (a / root)) : Vec3::Zero();
  }
  const std::size_t n = v.size();
  for (std::size_t a = 0; a < n; ++a) {
    phi += 0.5 * friction[a] * v[a].squaredNorm() - force[a].dot(v[a]);
    gradient[a] = friction[a] * v[a] - force[a];
  }
  gather(scratch_, gradient);
  return phi;
}

namespace {
double dot(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  double sum = 0.0;
  for (std::size_t a = 0; a < x.size(); ++a) sum += x[a].dot(y[a]);
  return sum;
}
}  // namespace

int EhdDrag::newton_direction(const ContactList& c, std::span<const double> friction,
                              double velocity_scale, double eta) {
  const std::size_t n = friction.size(), m = c.size();
  // Hessian data at the current point and the 3×3 diagonal blocks.
  const double floor = kHessianFloor * velocity_scale;
  for (std::size_t a = 0; a < n; ++a) block_inverse_[a] = friction[a] * Eigen::Matrix3d::Identity();
  for (std::size_t k = 0; k < m; ++k) {
    const double speed = w_[k].norm();
    s_[k] = geometry_.coefficient[k] / std::sqrt(std::max(speed, floor));
    unit_w_[k] = speed > 0.0 ? Vec3(w_[k] / speed) : Vec3::Zero();
    const Vec3& nk = geometry_.normal[k];
    const Eigen::Matrix3d block = s_[k] * (Eigen::Matrix3d::Identity() - nk * nk.transpose() -
                                           0.5 * unit_w_[k] * unit_w_[k].transpose());
    block_inverse_[c.i[k]] += block;
    block_inverse_[c.j[k]] += block;
  }
  for (auto& b : block_inverse_) b = b.inverse().eval();

  // H p = ζ p + Σ_c ±A_c (p_i − p_j),  A_c q = s_c (q − n(n·q) − ½ ŵ(ŵ·q)).
  const auto hessian_times = [&](const std::vector<Vec3>& in, std::vector<Vec3>& out) {
#pragma omp parallel for schedule(static) if (m >= kParallelContacts)
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3 q = in[c.i[k]] - in[c.j[k]];
      const Vec3& nk = geometry_.normal[k];
      scratch_[k] = s_[k] * (q - nk * nk.dot(q) - 0.5 * unit_w_[k] * unit_w_[k].dot(q));
    }
    for (std::size_t a = 0; a < n; ++a) out[a] = friction[a] * in[a];
    gather(scratch_, out);
  };

  const double target = eta * std::sqrt(dot(gradient_, gradient_));
  for (std::size_t a = 0; a < n; ++a) {
    step_[a].setZero();
    r_[a] = -gradient_[a];
    z_[a] = block_inverse_[a] * r_[a];
    p_[a] = z_[a];
  }
  double rz = dot(r_, z_);
  int iterations = 0;
  while (iterations < settings_.max_cg_iterations) {
    hessian_times(p_, hp_);
    const double alpha = rz / dot(p_, hp_);
    for (std::size_t a = 0; a < n; ++a) {
      step_[a] += alpha * p_[a];
      r_[a] -= alpha * hp_[a];
    }
    ++iterations;
    if (std::sqrt(dot(r_, r_)) <= target) break;
    for (std::size_t a = 0; a < n; ++a) z_[a] = block_inverse_[a] * r_[a];
    const double rz_next = dot(r_, z_);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t a = 0; a < n; ++a) p_[a] = z_[a] + beta * p_[a];
  }
  return iterations;
}

VelocitySolveStats EhdDrag::solve(const ContactList& c, double gamma_tilde,
                                  std::span<const double> friction,
                                  std::span<const Vec3> force, std::span<Vec3> v) {
  const std::size_t n = v.size();
  const std::size_t m = c.size();
  prepare(c, gamma_tilde);
  build_incidence(c, n);
  for (auto* vec : {&w_trial_, &unit_w_}) vec->resize(m);
  for (auto* vec : {&gradient_, &gradient_trial_, &trial_, &step_, &r_, &z_, &p_, &hp_}) vec->resize(n);
  block_inverse_.resize(n);
  s_.resize(m);
  VelocitySolveStats stats;

  double phi = objective(c, friction, force, v, w_, gradient_);
  if (settings_.coupling == DragCoupling::lagged) {
    // One sweep with the drag of the previous velocities: ζ v = F^e + F^EHD(v_prev).
    for (std::size_t a = 0; a < n; ++a) v[a] -= gradient_[a] / friction[a];
    stats.newton_iterations = 1;
    return stats;
  }

  // Predictor: one fixed-point sweep ζ v = F^e + F^EHD(v_prev) from the previous
  // velocities (the lagged scheme), kept only if it lowers Φ. It carries the new
  // elastic forces into v exactly, which is most of the change from one step to
  // the next when the drag is weak.
  for (std::size_t a = 0; a < n; ++a) trial_[a] = v[a] - gradient_[a] / friction[a];
  const double phi_predicted = objective(c, friction, force, trial_, w_trial_, gradient_trial_);
  if (phi_predicted < phi) {
    phi = phi_predicted;
    std::copy(trial_.begin(), trial_.end(), v.begin());
    w_.swap(w_trial_);
    gradient_.swap(gradient_trial_);
  }

  double first_norm = 0.0;
  for (int it = 0;; ++it) {
    double residual = 0.0, scale = 1.0;
    for (std::size_t a = 0; a < n; ++a) {
      residual = std::max(residual, gradient_[a].norm() / friction[a]);
      scale = std::max(scale, v[a].norm());
    }
    stats.residual = residual / scale;
    if (stats.residual <= settings_.tolerance) return stats;
    if (it == settings_.max_newton_iterations) {
      throw NumericalError(fmt::format(
          "EHD velocity solve did not converge in {} Newton iterations (residual {:.3g}, "
          "tolerance {:.3g})", it, stats.residual, settings_.tolerance));
    }
    ++stats.newton_iterations;

    // Inexact Newton: forcing term η → 0 as the gradient falls (superlinear).
    const double gnorm = std::sqrt(dot(gradient_, gradient_));
    if (it == 0) first_norm = gnorm;
    stats.cg_iterations += newton_direction(c, friction, scale, std::min(1e-6, std::sqrt(gnorm / first_norm)));

    // Backtracking line search on Φ (Armijo). Near convergence Φ's changes drop
    // below its rounding; then the Newton step is taken as it is.
    const double slope = dot(gradient_, step_);
    double t = 1.0;
    for (int halvings = 0;; ++halvings, t *= 0.5) {
      for (std::size_t a = 0; a < n; ++a) trial_[a] = v[a] + t * step_[a];
      const double phi_trial = objective(c, friction, force, trial_, w_trial_, gradient_trial_);
      const bool lost_in_rounding = std::abs(phi_trial - phi) <= 1e-14 * std::abs(phi);
      if (phi_trial <= phi + kArmijo * t * slope || lost_in_rounding || halvings == 40) {
        phi = phi_trial;
        break;
      }
    }
    std::copy(trial_.begin(), trial_.end(), v.begin());
    w_.swap(w_trial_);
    gradient_.swap(gradient_trial_);
  }
}

Eigen::Matrix3d EhdDrag::virial(const ContactList& c, double gamma_tilde, std::span<const Vec3> v,
                                std::span<Vec3> drag) const {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < c.size(); ++k) {
    Vec3 g = v[c.i[k]] - v[c.j[k]];
    g.x() += c.separation[k].y();
    const Vec3 n = c.separation[k].normalized();
    const Vec3 w = g - n * n.dot(g);
    const double speed = w.norm();
    if (speed == 0.0) continue;
    const double a = drag_coefficient(c, k, gamma_tilde);
    const Vec3 f = -a / std::sqrt(speed) * w;  // on i from j
    sum += c.separation[k] * f.transpose();
    if (!drag.empty()) {
      drag[c.i[k]] += f;
      drag[c.j[k]] -= f;
    }
  }
  return sum;
}

}  // namespace softglass::micro
