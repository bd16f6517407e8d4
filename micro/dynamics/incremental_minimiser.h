// The incremental (minimising-movement) problem behind the implicit integrator
// and the quasi-static shear: one backward-Euler step of the overdamped motion
// is the minimiser of a potential.
//
// The motion is a generalised gradient flow with a dissipation potential
// (docs/physics.md, "Motion"; Ortiz & Stainier's "variational constitutive updates",
// Mielke's doubly nonlinear flows): ζ_α v_α + ∂Ψ_EHD/∂v_α = F^e_α = −∂E/∂x_α,
// with Ψ_EHD(v) = Σ_c ⅔ a_c |P_c(v_i − v_j) + w⁰_c|^{3/2} the drag potential of
// ehd_drag.h (w⁰_c the affine tangential relative velocity), plus, with the
// Stokes friction against the neighbours, Σ_c ½ b_c |v_i − v_j + c d_y e_x|²
// (ζ_α is then its reservoir share). Backward Euler over
// a strain step h from the affinely sheared configuration x⁰, with non-affine
// displacement u = h v, is the stationarity condition of
//     Φ(u) = E(x⁰ + u) + Σ_α ζ_α |u_α|² / (2h) + h Ψ_EHD(u / h),
// which is why the scheme is unconditionally energy-stable: Φ(u) ≤ Φ(0) means
// E(x_{n+1}) + (dissipation) ≤ E(x⁰). The drag's geometry (contacts, normals,
// a_c, w⁰) is frozen at the start of the step; this is a first-order splitting
// whose effect is in the integrator's error estimate (backward_euler.cpp).
// With ζ = 0 and no drag, Φ = E: plain energy minimisation (quasi-static shear,
// aqs.h).
//
// Solver: inexact Newton with an Armijo backtracking line search on Φ
// (Nocedal & Wright, Numerical Optimization, ch. 3 and 7). Each Newton system
// is solved matrix-free by conjugate gradients with a 3×3 block-Jacobi
// preconditioner, to a relative residual η (the forcing term: Eisenstat &
// Walker's choice 2, floored so that no solve oversolves the exit test or
// the displacement test; `forcing_term` and `displacement_floor` in
// incremental_minimiser.cpp). The elastic Hessian of a
// contact, K_c = k_n n nᵀ − (|f|/r)(I − n nᵀ), is indefinite across the
// contact, and the total one loses definiteness at a
// plastic instability: CG stops at the first direction of non-positive
// curvature and returns the iterate so far (Steihaug's truncated CG), which is
// a descent direction, taken for this iteration; the next iteration's Hessian
// model is damped, H + μI (Levenberg–Marquardt), μ raised tenfold after each
// iteration that met such a direction and lowered tenfold after each full
// Newton step that met none. So Φ decreases monotonically, at every iteration.
// (The implicit step stops at that first direction instead: a step across an
// instability cannot be accurate — `stop_when_unstable`.)
// The solve stops when no net force exceeds its tolerance or, when the caller
// measures accuracy in distance (the implicit step), when the convergence
// rate of the last two Newton steps says the rest of it would move no particle
// by more than `move_tolerance`. (A
// sparse Cholesky factorisation was tried first: the fill-in of a periodic 3D
// contact network made it slower than CG already at N = 256, and the fill-in
// grows faster than N; bench/results/sparse_cholesky-2026-11-21.md.)

// The √|w| law: the curvature of ⅔ a |w|^{3/2} is a |w|^{−1/2}(P − θ ŵŵᵀ),
// unbounded as w → 0. Exactly as in the velocity solve (ehd_drag.h): θ = ½ is
// Newton, θ = 0 the tangent majoriser (a reweighted step), used for a contact
// while its |w| shrinks by more than 10 % per iteration; and |w| in the model
// is floored where the contact's drag falls below the force tolerance. The
// convergence test uses the exact gradient, so neither choice changes the
// answer, only the path to it.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "micro/dynamics/incremental_counters.h"
#include "micro/model/contact_system.h"
#include "micro/model/ehd_drag.h"
#include "micro/numerics/block_cg.h"

namespace softglass::micro {

/// The loosest residual a `loosen`ed solve accepts, relative to the mean
/// contact force. The implicit step's absolute tolerance grows like 1/h; at
/// very small steps it would exceed the forces themselves, the initial guess
/// would pass unchanged, and the step would be no step at all.
inline constexpr double kLoosestRelativeForce = 1e-3;

struct IncrementalSettings {
  /// Converged when max_α |∂Φ/∂u_α| ≤ this × the mean contact force, and ≤
  /// `absolute_force` if that is set (> 0) — or, with `loosen`, ≤ the larger
  /// of the two (the caller knows that `absolute_force` is accurate enough),
  /// but never above kLoosestRelativeForce × the mean contact force.
  double relative_force = 1e-9;
  double absolute_force = 0.0;
  bool loosen = false;
  /// Converged also when, after a full undamped Newton step, the displacement
  /// still to come is estimated below this (units of R, largest over the
  /// particles; 0: off) from the convergence rate of the last two such steps
  /// (within_move_tolerance in incremental_minimiser.cpp).
  double move_tolerance = 0.0;
  int max_iterations = 60;
  /// Stop at the first direction p of non-positive curvature that CG meets
  /// (`unstable`) instead of damping the Hessian model and going on. For the
  /// implicit step: backward Euler over a step h follows an unstable mode of
  /// the linearised motion (rate λ, a plastic instability) only while λh < 1,
  /// which is where its proximal term keeps Φ convex along the mode; CG's
  /// pᵀHp ≤ 0 certifies λh ≥ 1 along p, so the step cannot be accurate, and
  /// each attempt that went on was rejected after several Newton iterations.
  bool stop_when_unstable = false;
  /// Evaluate Φ at u = 0 too, and start from there if the guess is worse.
  /// The implicit steps turn it off: their guess is the step's predictor, and
  /// the extra force evaluation was 6.5 % of a run at γ̃ = 1e-9 (N = 1000).
  bool compare_guess = true;
};

/// The frozen drag of one step (from the contacts at the step's start).
struct FrozenDrag {
  FilmModel film{};  // P_c (film.h)
  std::vector<std::uint32_t> i, j;
  std::vector<Vec3> normal;         // n_c
  std::vector<double> coefficient;  // a_c (0 without EHD)
  std::vector<double> crossover;    // w* of a film of rest thickness (film.h), or 0
  std::vector<Vec3> affine;         // w⁰_c = P_c (c d_y e_x), or 0
  std::vector<double> dashpot;      // b_c of the Stokes pair dashpots (stokes_friction.h), or 0
  std::vector<double> shift;        // c d_y: the pair's affine relative velocity is c d_y e_x
  // P_c as a matrix, for the Hessian model: built once per step, not once per
  // Newton iteration.
  std::vector<Eigen::Matrix3d> projector;
  void clear();
  std::size_t size() const { return i.size(); }
};

/// The frozen drag's films at a point u: their sliding velocities w_c, speeds
/// |w_c|, secants and potentials (FilmLaw's at |w_c|), computed with Φ's
/// gradient and read again by the Hessian model and the relief test; and each
/// pair's relative non-affine velocity (u_i − u_j)/h.
struct Sliding {
  std::vector<Vec3> w, relative;
  std::vector<double> speed, secant, potential;
};

/// a_c = (¾ γ̃ R_c |f| √ε)^{1/2} (film.h), w⁰_c at shear rate c (`rate`, 1 in
/// steady shear) and the Stokes pair dashpots b_c (from the particles' Stokes
/// frictions ζ) of every contact of `contacts`.
void freeze_drag(const ContactList& contacts, double gamma_tilde, double rate,
                 const EhdSettings& settings, std::span<const double> friction, FrozenDrag& out);

struct IncrementalResult {
  bool converged = false;
  // A trial point left the neighbour list's reach after the accepted points had
  // used half of it: the system is back at the last accepted point x⁰ + u
  // (valid), and the caller rebuilds the list and goes on (or restarts).
  bool list_invalid = false;
  // The caller's `hopeless` test stopped the solve after an iteration: the
  // system is at the last accepted point x⁰ + u (valid), not converged.
  bool abandoned = false;
  // With stop_when_unstable: CG met non-positive curvature along p; the system
  // is at the last accepted point x⁰ + u. `convex_fraction` is the fraction s
  // of the step at which the proximal term, ∝ 1/(s h), would make the
  // curvature along p vanish (the rest of the Hessian model taken as fixed);
  // in (0, 1].
  bool unstable = false;
  double convex_fraction = 1.0;
  int iterations = 0;
  double residual = 0.0;  // max |∂Φ/∂u| at the end (units E* R²)
};

class IncrementalMinimiser {
 public:
  explicit IncrementalMinimiser(IncrementalSettings settings = {}) : settings_(settings) {}
  const IncrementalSettings& settings() const { return settings_; }
  void set_settings(const IncrementalSettings& s) { settings_ = s; }

  /// Minimises Φ from the configuration `system` is in (x⁰), starting at `u`
  /// (the guess on entry, the minimiser on return). `proximal` is ζ_α/h per
  /// particle (empty: none), `drag` the frozen drag (may be empty) and `h` the
  /// step. On return the system is at x⁰ + u with its forces computed there
  /// (also when `list_invalid`). If `energies` is given, Φ after each iteration is
  /// appended (relative to Φ at u = 0, then evaluated whatever compare_guess says).
  /// `max_iterations` ≥ 0 overrides the settings' limit for this call. `hopeless(u, move)`, if
  /// given, is asked after every accepted iteration with the iterate and the largest particle move
  /// of that iteration; true stops the solve (`abandoned`).
  using Hopeless = std::function<bool(const std::vector<Vec3>& u, double move)>;
  IncrementalResult minimise(ContactSystem& system, std::span<const double> proximal,
                             const FrozenDrag& drag, double h, std::vector<Vec3>& u,
                             std::vector<double>* energies = nullptr, int max_iterations = -1,
                             const Hopeless& hopeless = {});

  const IncrementalCounters& counters() const { return counters_; }

 private:
  struct Value {
    double elastic;      // E
    double proximal;     // Σ ζ|u|²/2h
    double dissipation;  // h Ψ(u/h)
  };
  /// Moves the system to x⁰ + u and evaluates forces, Φ's parts and ∇Φ.
  bool evaluate_at(ContactSystem& system, std::span<const double> proximal, const FrozenDrag& drag,
                   double h, const std::vector<Vec3>& u, Value& value, std::vector<Vec3>& gradient,
                   Sliding& sliding);
  /// The Hessian model's pair blocks and the inverted diagonal blocks.
  void assemble(const ContactSystem& system, std::span<const double> proximal,
                const FrozenDrag& drag, double h, double force_floor);
  void assemble_elastic(const ContactList& contacts);
  void add_drag(const FrozenDrag& drag, double h, double force_floor);
  void hessian_times(std::span<const double> proximal, const std::vector<Vec3>& in,
                     std::vector<Vec3>& out) const;
  /// Leaves the direction in direction_; returns the CG iterations.
  int newton_direction(std::span<const double> proximal, double eta);
  double damped_newton_direction(std::span<const double> proximal, double eta);
  double convex_fraction(std::span<const double> proximal) const;
  enum class LineSearch { accepted, failed, list_invalid };
  LineSearch line_search(ContactSystem& system, std::span<const double> proximal,
                         const FrozenDrag& drag, double h, const std::vector<Vec3>& u, Value& value,
                         Value& trial_value, double& t);

  IncrementalSettings settings_;
  IncrementalCounters counters_;
  // The configuration x⁰ and its list bookkeeping.
  std::vector<Vec3> base_;
  ContactSystem::Tracking base_tracking_;
  double base_strain_ = 0.0;
  std::vector<Vec3> origin_;  // u = 0, kept to spare an allocation per solve
  std::vector<Vec3> gradient_, gradient_trial_, trial_, direction_;
  Sliding sliding_, sliding_trial_;
  std::vector<double> relief_;  // θ_c
  std::vector<std::uint32_t> pair_i_, pair_j_;
  std::vector<Eigen::Matrix3d> block_, diagonal_, undamped_diagonal_;
  mutable std::vector<double> padded_product_;  // hessian_times' scratch
  double damping_ = 0.0;         // μ
  double diagonal_scale_ = 1.0;  // mean diagonal entry of the Hessian model
  bool negative_curvature_ = false;
  void invert_diagonal();
  CgWorkspace cg_;
};

}  // namespace softglass::micro
