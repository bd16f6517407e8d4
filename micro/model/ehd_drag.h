// Elastohydrodynamic (EHD) drag and the velocities it makes implicit.
//
// Drag on α from β (docs/physics.md, "EHD drag"), in reduced units (forces E* R²,
// velocities γ̇ R):
//     f^EHD = −a_c |w|^{1/2} ŵ,     a_c = ( γ̃ C R_c³ ε^{(2n+1)/2} )^{1/2},
// with w the tangential part of the relative velocity (including the affine
// flow), or another projection of it (film.h). Because C ε^n = ¾ F(ε) for every law, a_c² = ¾ γ̃
// R_c³ F(ε) √ε = ¾ γ̃ R_c |f| √ε: the drag needs only the elastic force, so it follows any contact
// law.
//
// Velocities. Overdamped motion, u_α = u∞(x_α) + (m_α/γ̃)(F^e_α + F^EHD_α) with
// m_α = f_r/(6π R_α). Writing v = u − u∞ for the non-affine velocity and
// ζ_α = γ̃/m_α for the friction, v solves
//     ζ_α v_α − F^EHD_α(v) = F^e_α ,
// in which the relative velocity of a contact is v_i − v_j + c d_y e_x (c the
// shear rate in units of that of γ̃, shear_drive.h; 1 in steady shear). This is the
// stationarity condition of the strictly convex function
//     Φ(v) = Σ_α ½ ζ_α |v_α|² + Σ_c ⅔ a_c |P_c(v_i − v_j + c d_y e_x)|^{3/2} − Σ_α F^e_α·v_α ,
// (with the Stokes friction against the neighbours, stokes_friction.h, ζ_α is
// its reservoir share and Φ gains Σ_c ½ b_c |v_i − v_j + c d_y e_x|²: quadratic,
// convex, one more term of the same kind in every step below)
// (P_c projects on the contact plane), so the solution exists, is unique, and is
// found in two phases. First nonlinear Jacobi sweeps, v_α ← v_α − ∇_αΦ / D_α with
// D_α = ζ_α + ¾ Σ_c a_c/√|w_c| (the friction plus the particle's own drag
// stiffness), kept while each at least halves the residual: one contact pass
// each, and at γ̃ ≳ 1e-6, where the drag is a correction to the friction, a
// warm-started solve converges in a few of them. Then, when the sweeps stall or
// diverge (low γ̃, drag dominant), a Newton-type method with a backtracking line
// search on Φ.
//
// The √u∥ law. The Hessian of ⅔|w|^{3/2} is |w|^{−1/2}(P − ½ŵŵ): unbounded as
// w → 0, and a poor model when a contact approaches a small |w*| from above: the
// drag a√|w| is concave in |w|, so the Newton tangent overshoots past w* (even
// past 0) and the iteration crawls. Each contact therefore gets the curvature
// |w|^{−1/2}(P − θ_c ŵŵ), where θ_c = 0 is the tangent majoriser of the concave
// |w|^{3/2} = (|w|²)^{3/4} (the Kačanov / iteratively reweighted step, which moves
// |w| to about √(|w||w*|), closing a gap of decades in a few iterations) and
// θ_c = ½ the exact Hessian. A contact uses the majoriser while its |w| shrinks
// by more than 10 % per iteration — and, after an iteration that did not halve
// the residual (a crawl), while it shrinks at all — and Newton otherwise
// (approaching from below, Newton cannot overshoot a concave law), which gives
// quadratic convergence at the end (docs/numerics.md measures it against pure
// Newton, which stalls). Both models are positive
// definite, so every direction is a descent direction and the line search on Φ
// makes the method globally convergent. In the model only, |w| is floored where
// the contact's drag falls below the force tolerance; convergence is judged on
// the exact gradient.
// Each Newton system is solved by conjugate gradients with a 3×3 block-Jacobi
// preconditioner (the Hessian is symmetric positive definite).
//
// `lagged` coupling replaces all this by one fixed-point sweep per step: the
// drag is evaluated with the previous velocities. It is there to measure what
// that shortcut costs (docs/numerics.md); it diverges when the drag dominates
// the friction, i.e. at low γ̃.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "micro/contact/contact_forces.h"
#include "micro/model/film.h"
#include "micro/model/stokes_friction.h"
#include "micro/model/wall_films.h"
#include "micro/numerics/block_cg.h"

namespace softglass::micro {

enum class DragCoupling { implicit, lagged };
DragCoupling parse_drag_coupling(const std::string& name);
std::string to_string(DragCoupling coupling);

struct EhdSettings {
  bool enabled = true;
  FilmModel film{};         // which relative velocity the drag acts on (film.h)
  StokesFriction stokes{};  // what the Stokes friction acts against (stokes_friction.h)
  DragCoupling coupling = DragCoupling::implicit;
  double rest_thickness = 0.0;  // h0/R of the films (film.h); 0: the paper's √|w| law
  double tolerance = 1e-6;      // velocity residual relative to max(1, max|v|)
  int max_newton_iterations = 60;
  int max_cg_iterations = 1000;

  void validate() const;
};

struct VelocitySolveStats {
  int fixed_point_sweeps = 0;
  int newton_iterations = 0;
  int cg_iterations = 0;
  double residual = 0.0;  // final, relative
};

/// The virial of the dissipative pair forces in two parts: the EHD drag of the
/// films (the paper's σ^v, "due to the EHD drag force") and, with the Stokes
/// friction against the neighbours, its pair dashpots (stokes_friction.h;
/// zero against the affine flow, where the friction is a one-body force
/// without a virial).
struct DissipativeVirial {
  Eigen::Matrix3d film = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d friction = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d total() const { return film + friction; }
};

class EhdDrag {
 public:
  explicit EhdDrag(EhdSettings settings);
  const EhdSettings& settings() const { return settings_; }

  /// Non-affine velocities v for the given contacts, Stokes frictions ζ
  /// (6π γ̃ R/f_r) and elastic forces, under the affine flow c y e_x at shear
  /// rate c (`rate`, in units of the rate of γ̃: 1 in steady shear); `v` holds
  /// the initial guess on entry; `walls` the particles' wall contacts, whose
  /// films (wall_films.h) join the pairs'. Throws NumericalError if Newton fails.
  VelocitySolveStats solve(const ContactList& contacts, double gamma_tilde, double rate,
                           std::span<const double> friction, std::span<const Vec3> elastic_force,
                           std::span<Vec3> v, const WallContacts& walls = kNoWalls);

  /// The drag of each wall film on its particle at velocities v and rate c
  /// (into `per_film`, sized like `walls`), and their sum per particle in
  /// `drag` if not empty. The walls take the opposite forces.
  void wall_drag(const WallContacts& walls, double gamma_tilde, double rate,
                 std::span<const Vec3> v, std::span<Vec3> per_film,
                 std::span<Vec3> drag = {}) const;

  /// Σ_c d ⊗ f at velocities v and shear rate c of the pair forces that
  /// dissipate, each part apart (σ^v = −(film + friction)/V); also the sum of
  /// those forces on each particle if `drag` is not empty, and each
  /// contact's (on i from j) if `per_contact` is not empty. `friction` (ζ) is
  /// needed for the dashpots only.
  DissipativeVirial virial(const ContactList& contacts, double gamma_tilde, double rate,
                           std::span<const Vec3> v, std::span<Vec3> drag = {},
                           std::span<const double> friction = {},
                           std::span<Vec3> per_contact = {}) const;

 private:
  struct Geometry {  // per contact
    std::vector<Vec3> normal;
    std::vector<double> coefficient;  // a_c (0 without EHD)
    std::vector<double> crossover;    // w* of a film of rest thickness (film.h), or 0
    std::vector<Vec3> affine;         // w⁰_c
    std::vector<double> dashpot;      // b_c (stokes_friction.h; 0 for `affine`)
  };
  void prepare(const ContactList& contacts, double gamma_tilde, double rate,
               std::span<const double> friction);
  void build_incidence(const ContactList& contacts, std::size_t n);
  /// ∇Φ(v); leaves the tangential relative velocities in `w` (and the wall
  /// films' in their current or `trial` buffer).
  void gradient_at(const ContactList& contacts, std::span<const Vec3> force,
                   std::span<const Vec3> v, std::vector<Vec3>& w, std::vector<Vec3>& gradient,
                   bool trial);
  /// Φ(v + tδ) − Φ(v) for the Newton step δ, without cancellation, and a bound
  /// on its rounding error; leaves the trial point, its tangential velocities
  /// and gradient in the trial buffers.
  struct Change {
    double value, rounding;
  };
  Change change_along_step(const ContactList& contacts, std::span<const Vec3> force,
                           std::span<const Vec3> v, double t);
  /// max_α |g_α|/ζ_α relative to max(1, max|v|), and that scale.
  struct Residual {
    double residual, scale;
  };
  Residual relative_residual(const std::vector<Vec3>& gradient, std::span<const Vec3> at,
                             std::span<const double> friction) const;
  /// The two phases of solve(): nonlinear Jacobi sweeps (returns how many were
  /// kept), then Newton with a line search.
  int jacobi_sweeps(const ContactList& contacts, std::span<const double> friction,
                    std::span<const Vec3> force, std::span<Vec3> v, Residual& r);
  void newton(const ContactList& contacts, std::span<const double> friction,
              std::span<const Vec3> force, std::span<Vec3> v, Residual r,
              VelocitySolveStats& stats);
  void line_search(const ContactList& contacts, std::span<const Vec3> force,
                   std::span<const Vec3> v, double gnorm);
  /// Adds per-contact vectors to particles: out_α += Σ_{c∋α} ±y_c.
  void gather(std::span<const Vec3> per_contact, std::span<Vec3> out) const;
  /// Newton direction: H δ = −g by block-Jacobi preconditioned CG to ‖r‖ ≤ η‖g‖.
  int newton_direction(const ContactList& contacts, std::span<const double> friction,
                       double velocity_scale, double eta);

  static const WallContacts kNoWalls;

  EhdSettings settings_;
  Geometry geometry_;
  WallFilms walls_;  // the one-body films of the wall contacts
  std::vector<double> wall_secant_;  // Σ of a particle's wall films' secants (Jacobi)
  double rate_ = 1.0;          // c of the solve in progress
  std::vector<Vec3> scratch_;  // per-contact vectors
  std::vector<std::size_t> incidence_start_;
  std::vector<std::uint32_t> incidence_;  // contact index × 2 + (0: i side, 1: j side)
  // Newton state, reused between solves: current and trial points.
  std::vector<Vec3> w_, w_trial_, gradient_, gradient_trial_, trial_;
  std::vector<Vec3> step_;
  CgWorkspace cg_;
  std::vector<Eigen::Matrix3d> block_inverse_;
  std::vector<double> s_;          // a_c / √max(|w|, floor)
  std::vector<double> relief_;     // θ_c: ½ (Newton) or 0 (majoriser)
  std::vector<double> secant_;     // a_c / √|w_c| at the last gradient
  std::vector<Vec3> unit_w_;       // ŵ
  std::vector<double> reservoir_;  // the friction against the affine flow, per particle
};

}  // namespace softglass::micro
