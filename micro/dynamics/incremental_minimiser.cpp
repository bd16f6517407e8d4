#include "micro/dynamics/incremental_minimiser.h"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "micro/numerics/pair_block_product.h"

namespace softglass::micro {

namespace {
constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 40;
// The forcing term of the first Newton iteration, and the largest of any.
constexpr double kMaxForcing = 0.1;
// Largest move of one particle along a Newton direction (units of R): beyond
// it the quadratic model says little, and the neighbour list would need a
// rebuild. The direction is scaled down, not rejected.
constexpr double kMaxMove = 0.1;

double max_norm(const std::vector<Vec3>& x) {
  double worst = 0.0;
  for (const Vec3& v : x) worst = std::max(worst, v.squaredNorm());
  return std::sqrt(worst);
}

// The forcing term η_k of Newton iteration k > 0: CG stops at ‖r‖₂ ≤ η_k ‖g_k‖₂.
// Eisenstat & Walker's choice 2 (SIAM J. Sci. Comput. 17 (1996) 16–32) with
// γ = 0.9, α = 2, as Kelley uses it (Iterative Methods for Linear and Nonlinear
// Equations, SIAM 1995, §6.3): η_k = γ (‖g_k‖₂/‖g_{k−1}‖₂)² asks each linear
// solve to be as accurate as the last outer step has shown the Newton model to
// be, quadratically so once it converges. (Their safeguard against a lucky drop
// of ‖g‖, η_k ≥ γ η_{k−1}² while that is above 0.1, cannot act under the cap
// kMaxForcing = 0.1.) Kelley's floor η_k ≥ ½ τ/‖g_k‖ stops the last solve short
// of oversolving the exit test τ. That test is on the largest force, ‖g‖_∞ ≤ τ,
// so the floor is taken in its norm: ½ τ/‖g_k‖_∞ asks for a residual of half the
// tolerance measured in the current gradient's shape. (With 1 instead of ½,
// more steps ended just above τ and took one more Newton iteration;
// bench/results/forcing_term-2026-11-27.md.) The √(‖g_k‖/‖g_0‖) rule used before
// asked for up to 30 times the accuracy the test needed in the last iteration,
// and converged only linearly, by about a decade per iteration; measured in
// docs/integrators.md ("The forcing term").
double forcing_term(double gnorm, double last_gnorm, double largest_force, double tolerance) {
  constexpr double gamma = 0.9;
  const double ratio = gnorm / last_gnorm;
  return std::min(kMaxForcing, std::max(gamma * ratio * ratio, 0.5 * tolerance / largest_force));
}

// The forcing term's floor for the displacement test (below; μ =
// IncrementalSettings::move_tolerance, 0: off), after a full undamped Newton
// step that moved no particle by more than δ (0: not such a step). Kelley's
// floor keeps a solve from oversolving the force test; this one keeps it from
// oversolving the displacement test. The next correction is shorter than δ
// (Newton converges, or the rate test cannot pass), and CG stopped at a
// relative residual η leaves it off by about η times its length: η = ½ μ/δ
// puts that error near ½ θ μ, θ the rate, well inside the test's μ. An
// estimate, not a bound (CG's error can exceed η times the correction by up to
// the Hessian's condition number). The Eisenstat–Walker term alone asked the
// second Newton solve of an implicit step for a tight η, and so for most of
// the CG iterations, on the correction on which the rate test usually ends
// (docs/integrators.md, "Stopping the Newton iteration"; measured in
// bench/results/displacement_floor-2026-11-29-zen3.md).
double displacement_floor(double last_move, double move_tolerance) {
  if (!(move_tolerance > 0.0) || !(last_move > 0.0)) return 0.0;
  return std::min(kMaxForcing, 0.5 * move_tolerance / last_move);
}

// The displacement test (IncrementalSettings::move_tolerance) after a full,
// undamped Newton step that moved no particle by more than `move`, the one
// before having moved them by `last` (0: not such a step). Newton's iterates
// close in on the solution at the rate θ = move/last; what remains is then
// about θ/(1 − θ) × move (Hairer & Wanner, Solving ODEs II, IV.8, the stopping
// rule of the simplified Newton iteration of implicit Runge–Kutta steps; CVODE
// stops its Newton iteration the same way, at a tenth of the local error
// test). Without a rate (the first such step) the move itself is the estimate.
bool within_move_tolerance(double move, double last, double tolerance) {
  const double remaining = last > move ? move * move / (last - move) : move;
  return remaining <= tolerance;
}

// Whether every component of u is +0, bit for bit: then Φ at u is Φ at the
// origin, evaluated from the very same input (−0 is not taken for +0: it can
// turn the sign of a zero gradient component).
bool is_origin(const std::vector<Vec3>& u) {
  return std::all_of(u.begin(), u.end(), [](const Vec3& v) {
    return std::bit_cast<std::uint64_t>(v.x()) == 0 && std::bit_cast<std::uint64_t>(v.y()) == 0 &&
           std::bit_cast<std::uint64_t>(v.z()) == 0;
  });
}

// The frozen drag's block (a/h)|w|^{-1/2}(P − θ ŵŵᵀ), |w| floored (see the
// header), plus (b/h) I of the Stokes pair dashpots, for drag pair k at the
// point `sliding` was evaluated at, with relief θ (`inverse_step` is 1/h). A
// free function called once, so that it is inlined: returned from a call, the
// block went through the stack as scalars and was reloaded as packets,
// stalling on the partial stores. The only division left on the common path
// is ŵ's: the floor's test compares squares, and 1/h is taken once.
Eigen::Matrix3d drag_block(const FrozenDrag& drag, std::size_t k, const Sliding& sliding,
                           double relief, double inverse_step, double force_floor) {
  const double a = drag.coefficient[k];
  const double dashpot = drag.dashpot[k] * inverse_step;
  Eigen::Matrix3d b;
  if (a <= 0.0) {
    b = dashpot * Eigen::Matrix3d::Identity();
    return b;
  }
  const Vec3& w = sliding.w[k];
  const double speed = sliding.speed[k];
  const FilmLaw law{a, drag.crossover[k]};
  // The secant at max(|w|, floor): the one evaluate_at computed, unless the
  // film's drag a|w|^{1/2} is below the floor, i.e. |w| < (floor/a)².
  const bool floored = a * a * speed < force_floor * force_floor;
  const double s =
      (floored ? law.secant((force_floor / a) * (force_floor / a)) : sliding.secant[k]) *
      inverse_step;
  // A film in its linear regime has the isotropic curvature s P: no relief;
  // nor has a film whose relief θ is 0 (the majoriser).
  Vec3 unit = Vec3::Zero(), relieved = Vec3::Zero();
  if (relief > 0.0 && speed > 0.0 && !law.linear(speed)) {
    unit = w / speed;
    relieved = relief * unit;
  }
  const Eigen::Matrix3d& projector = drag.projector[k];
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row)
      b(row, col) =
          (row == col ? dashpot : 0.0) + s * (projector(row, col) - relieved[row] * unit[col]);
  return b;
}
}  // namespace

void FrozenDrag::clear() {
  i.clear();
  j.clear();
  normal.clear();
  projector.clear();
  coefficient.clear();
  crossover.clear();
  affine.clear();
  dashpot.clear();
  shift.clear();
}

void freeze_drag(const ContactList& c, double gamma_tilde, double rate, const EhdSettings& settings,
                 std::span<const double> friction, FrozenDrag& out) {
  // Sized once and filled by index: appended element by element, each of the
  // eight arrays went through a call to grow it per contact.
  const std::size_t pairs = c.size();
  out.film = settings.film;
  out.i.assign(c.i.begin(), c.i.end());
  out.j.assign(c.j.begin(), c.j.end());
  out.normal.resize(pairs);
  out.projector.resize(pairs);
  out.coefficient.resize(pairs);
  out.crossover.resize(pairs);
  out.affine.resize(pairs);
  out.shift.resize(pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    const Vec3 n = c.separation[k].normalized();
    out.normal[k] = n;
    out.projector[k] = settings.film.projector(n);
    const double a = settings.enabled ? film_coefficient(gamma_tilde, c.contact_radius[k],
                                                         c.force[k], c.deformation[k])
                                      : 0.0;
    out.coefficient[k] = a;
    out.crossover[k] = film_crossover(settings.rest_thickness, gamma_tilde, a,
                                      c.contact_radius[k], c.deformation[k]);
    out.affine[k] = settings.film.affine(n, c.separation[k], rate);
    out.shift[k] = rate * c.separation[k].y();
  }
  settings.stokes.pair_coefficients(c, friction, out.dashpot);
}

bool IncrementalMinimiser::evaluate_at(ContactSystem& system, std::span<const double> proximal,
                                       const FrozenDrag& drag, double h, const std::vector<Vec3>& u,
                                       Value& value, std::vector<Vec3>& gradient,
                                       Sliding& sliding) {
  system.restore_positions(base_, base_strain_);
  system.restore_tracking(base_tracking_);
  system.move(1.0, u);
  if (!system.neighbours().valid_for(system.max_nonaffine_displacement(), base_strain_))
    return false;
  const ContactField& field =
      system.compute_forces({.energy = true, .contacts = true, .virial = false});
  ++counters_.force_evaluations;
  const std::size_t n = u.size();
  value.elastic = field.energy;
  double proximal_sum = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    gradient[a] = -field.force[a];
    if (!proximal.empty()) {
      gradient[a] += proximal[a] * u[a];
      proximal_sum += 0.5 * proximal[a] * u[a].squaredNorm();
    }
  }
  value.proximal = proximal_sum;
  // In three passes: the films' sliding velocities (gathered by pair), their
  // laws over the arrays (evaluate_films), and the forces scattered back.
  const std::size_t pairs = drag.size();
  std::vector<Vec3>& w = sliding.w;
  std::vector<Vec3>& du = sliding.relative;
  w.resize(pairs);
  du.resize(pairs);
  sliding.speed.resize(pairs);
  sliding.secant.resize(pairs);
  sliding.potential.resize(pairs);
  const double inverse_step = 1.0 / h;
  for (std::size_t k = 0; k < pairs; ++k) {
    du[k] = (u[drag.i[k]] - u[drag.j[k]]) * inverse_step;
    w[k] = drag.film.project(drag.normal[k], du[k]) + drag.affine[k];
    sliding.speed[k] = w[k].squaredNorm();
  }
  evaluate_films(drag.coefficient, drag.crossover, sliding.speed, sliding.secant,
                 sliding.potential);
  // The sums run in a local and are stored once: added to `value` in place,
  // each addition waited for the store of the one before (the gradient's
  // stores may alias it).
  double dissipation = 0.0;
  for (std::size_t k = 0; k < pairs; ++k) {
    dissipation += h * sliding.potential[k];
    Vec3 f = w[k] * sliding.secant[k];                // a |w|^{1/2} ŵ on the EHD branch (film.h)
    if (const double b = drag.dashpot[k]; b > 0.0) {  // h · ½ b |q⁰|², q⁰ = du + c d_y e_x
      const Vec3 q0(du[k].x() + drag.shift[k], du[k].y(), du[k].z());
      dissipation += h * 0.5 * b * q0.squaredNorm();
      f += b * q0;
    }
    gradient[drag.i[k]] += f;
    gradient[drag.j[k]] -= f;
  }
  value.dissipation = dissipation;
  return true;
}

void IncrementalMinimiser::assemble(const ContactSystem& system, std::span<const double> proximal,
                                    const FrozenDrag& drag, double h, double force_floor) {
  ++counters_.assemblies;
  const std::size_t n = system.size();
  const ContactList& contacts = system.forces().contacts;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  diagonal_.resize(n);
  for (std::size_t a = 0; a < n; ++a)
    diagonal_[a] = (proximal.empty() ? 0.0 : proximal[a]) * identity;
  assemble_elastic(contacts);
  add_drag(drag, h, force_floor);
  // Block-Jacobi preconditioner; a particle without contacts or friction (a
  // rattler in quasi-static shear) gets a tiny diagonal instead of none.
  double scale = 0.0;
  for (const auto& d : diagonal_) scale += d.trace();
  diagonal_scale_ = scale / (3.0 * double(std::max<std::size_t>(n, 1)));
  undamped_diagonal_ = diagonal_;
  invert_diagonal();
}

// The blocks are written entry by entry, in the order of operations of the
// matrix expressions in the comments (so to the last bit): built as Eigen
// expressions, their 3×3 temporaries went through the stack in halves and
// whole packets, whose reloads stalled on the partial stores.
//
// Elastic contacts at the current point: K_c = k_n nnᵀ − (|f|/r)(I − nnᵀ); the
// preconditioner takes |K_c| = k_n nnᵀ + (|f|/r)(I − nnᵀ), positive definite.
// Entry by entry, with p = k_n (nnᵀ)_ab and q = (|f|/r)(I − nnᵀ)_ab, K_c is
// p − q and |K_c| is p + q.
void IncrementalMinimiser::assemble_elastic(const ContactList& c) {
  pair_i_.assign(c.i.begin(), c.i.end());
  pair_j_.assign(c.j.begin(), c.j.end());
  block_.resize(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3 nk = c.separation[k] * c.inverse_distance[k];
    const double stiffness = c.stiffness[k];
    const double tangential = c.force[k] * c.inverse_distance[k];
    Eigen::Matrix3d& block = block_[k];
    Eigen::Matrix3d& di = diagonal_[c.i[k]];
    Eigen::Matrix3d& dj = diagonal_[c.j[k]];
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) {
        const double nn = nk[row] * nk[col];
        const double p = stiffness * nn;
        const double q = tangential * ((row == col ? 1.0 : 0.0) - nn);
        block(row, col) = p - q;
        di(row, col) += p + q;
        dj(row, col) += p + q;
      }
  }
}

// The drag's pairs are mostly the elastic ones, listed in the same order (both
// come from the same neighbour list, particle by particle): a drag block is
// added to its pair's elastic block when there is one, halving the product's
// work. The search for it starts at the block after the last one matched,
// where the same order puts it, and falls back to the particle's first block.
void IncrementalMinimiser::add_drag(const FrozenDrag& drag, double h, double force_floor) {
  const std::size_t elastic_pairs = block_.size();
  const double inverse_step = 1.0 / h;
  std::size_t cursor = 0, next = 0;
  for (std::size_t k = 0; k < drag.size(); ++k) {
    if (drag.coefficient[k] <= 0.0 && drag.dashpot[k] <= 0.0) continue;
    const Eigen::Matrix3d b = drag_block(drag, k, sliding_, relief_[k], inverse_step, force_floor);
    diagonal_[drag.i[k]] += b;
    diagonal_[drag.j[k]] += b;
    const auto matches = [&](std::size_t m) {
      return m < elastic_pairs && pair_i_[m] == drag.i[k] && pair_j_[m] == drag.j[k];
    };
    std::size_t match = next;
    if (!matches(match)) {
      while (cursor < elastic_pairs && pair_i_[cursor] < drag.i[k]) ++cursor;
      match = cursor;
      while (match < elastic_pairs && pair_i_[match] == drag.i[k] && pair_j_[match] != drag.j[k])
        ++match;
    }
    if (matches(match)) {
      block_[match] += b;
      next = match + 1;
    } else {
      pair_i_.push_back(drag.i[k]);
      pair_j_.push_back(drag.j[k]);
      block_.push_back(b);
    }
  }
}

void IncrementalMinimiser::invert_diagonal() {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const double floor = 1e-12 * std::max(diagonal_scale_, 1e-300);
  for (std::size_t a = 0; a < diagonal_.size(); ++a)
    diagonal_[a] = (undamped_diagonal_[a] + (damping_ + floor) * identity).inverse();
}

// H x: the pair blocks' product (numerics/pair_block_product.h) with the
// proximal term and the damping μ on the diagonal.
void IncrementalMinimiser::hessian_times(std::span<const double> proximal,
                                         const std::vector<Vec3>& in,
                                         std::vector<Vec3>& out) const {
  pair_block_product({pair_i_, pair_j_, block_}, proximal, damping_, in, out, padded_product_);
}

int IncrementalMinimiser::newton_direction(std::span<const double> proximal, double eta) {
  // Truncated at non-positive curvature (plastic instabilities): the caller
  // then raises the damping for the next iteration, or stops.
  const int limit = static_cast<int>(std::max<std::size_t>(50, 3 * gradient_.size()));
  // A uniform translation meets only the proximal (friction) term and the
  // damping. Without friction (quasi-static shear) it is a null mode of the
  // elastic energy that the gradient has no part in: no coarse correction.
  double translation_stiffness = 0.0;
  if (!proximal.empty())
    for (const double p : proximal) translation_stiffness += p + damping_;
  const CgOutcome outcome = solve_newton_system(
      gradient_,
      [&](const std::vector<Vec3>& in, std::vector<Vec3>& out) {
        hessian_times(proximal, in, out);
      },
      // The inverted diagonal by a pointer copied in (see block_cg.h, two_level_precondition).
      [inverse = diagonal_.data()](std::size_t a, const Vec3& v) -> Vec3 { return inverse[a] * v; },
      translation_stiffness, eta, limit, true, direction_, cg_);
  negative_curvature_ = outcome.negative_curvature;
  return outcome.iterations;
}

// Armijo backtracking on Φ along direction_ from u, which leaves the trial
// point (step t) in the trial buffers when it is accepted. The change is the
// sum of the parts' changes; near the minimum it can fall below their
// rounding, and then the step is judged by the gradient. A trial beyond the
// neighbour list's reach is shortened like one that fails the Armijo test, as
// long as the accepted point has used less than half the reach; past that, the
// caller's rebuild around the accepted point gains more, and it always leaves a
// reach for the next step: the system is then back at u (`list_invalid`).
IncrementalMinimiser::LineSearch IncrementalMinimiser::line_search(
    ContactSystem& system, std::span<const double> proximal, const FrozenDrag& drag, double h,
    const std::vector<Vec3>& u, Value& value, Value& trial_value, double& t) {
  const std::size_t n = u.size();
  const double reach = system.neighbours().nonaffine_reach(base_strain_);
  const bool rebuild_pays = system.max_nonaffine_displacement() > 0.5 * reach;
  const double slope = dot(gradient_, direction_);
  const double gnorm2 = dot(gradient_, gradient_);
  t = 1.0;
  for (int halvings = 0; halvings < kMaxHalvings; ++halvings, t *= 0.5) {
    if (halvings > 0) ++counters_.backtracks;
    for (std::size_t a = 0; a < n; ++a) trial_[a] = u[a] + t * direction_[a];
    if (!evaluate_at(system, proximal, drag, h, trial_, trial_value, gradient_trial_,
                     sliding_trial_)) {
      if (!rebuild_pays) continue;
      evaluate_at(system, proximal, drag, h, u, value, gradient_, sliding_);  // back to u
      return LineSearch::list_invalid;
    }
    const double change = (trial_value.elastic - value.elastic) +
                          (trial_value.proximal - value.proximal) +
                          (trial_value.dissipation - value.dissipation);
    const double rounding =
        64.0 * std::numeric_limits<double>::epsilon() *
        (std::abs(value.elastic) + std::abs(trial_value.elastic) + value.proximal +
         trial_value.proximal + value.dissipation + trial_value.dissipation);
    if (change <= kArmijo * t * slope ||
        (std::abs(change) <= rounding && dot(gradient_trial_, gradient_trial_) < gnorm2))
      return LineSearch::accepted;
  }
  evaluate_at(system, proximal, drag, h, u, value, gradient_, sliding_);  // leave the system at u
  return LineSearch::failed;
}

// Along CG's last direction p (where it met pᵀHp ≤ 0): the proximal part
// q = Σ_α ζ_α/h |p_α|² scales like 1/h, the rest c = pᵀHp − q is held fixed,
// so the curvature c + q/s is positive for s < q/(−c).
double IncrementalMinimiser::convex_fraction(std::span<const double> proximal) const {
  const std::vector<Vec3>& p = cg_.p;
  double q = 0.0;
  for (std::size_t a = 0; a < proximal.size(); ++a) q += proximal[a] * p[a].squaredNorm();
  const double rest = dot(p, cg_.hp) - q;
  if (!(q > 0.0) || !(rest < 0.0)) return 1.0;
  return std::min(1.0, q / -rest);
}

// The Newton direction of the Hessian model damped by the Levenberg–Marquardt
// μ, shortened so that no particle moves more than kMaxMove; returns the
// largest particle move along it. Where CG meets non-positive curvature (and
// the solve goes on through it: not stop_when_unstable), the iterate so far is
// still a descent direction (Steihaug) and is taken as it is; μ is raised
// tenfold for the next iteration's model. Solving again at once with the
// raised μ threw that truncated solve away, and in a plastic event, where μ
// sits where the model is barely convex, most iterations did so: quasi-static
// shear takes markedly fewer CG iterations without it, its yield stress
// unchanged within the runs' scatter (docs/integrators.md, "Damping through a
// plastic event"; bench/results/aqs_damping-2026-11-29-zen3.md).
double IncrementalMinimiser::damped_newton_direction(std::span<const double> proximal, double eta) {
  counters_.cg_iterations += static_cast<std::size_t>(newton_direction(proximal, eta));
  if (negative_curvature_ && !settings_.stop_when_unstable) {
    ++counters_.damping_raises;
    damping_ = std::max(10.0 * damping_, 1e-4 * diagonal_scale_);
  }
  const double longest = max_norm(direction_);
  if (longest <= kMaxMove) return longest;
  for (auto& d : direction_) d *= kMaxMove / longest;
  return kMaxMove;
}

IncrementalResult IncrementalMinimiser::minimise(
    ContactSystem& system, std::span<const double> proximal, const FrozenDrag& drag, double h,
    std::vector<Vec3>& u, std::vector<double>* energies, int max_iterations,
    const Hopeless& hopeless) {
  if (max_iterations < 0) max_iterations = settings_.max_iterations;
  const std::size_t n = system.size();
  IncrementalResult result;
  ++counters_.solves;
  base_.assign(system.particles().position.begin(), system.particles().position.end());
  system.save_tracking(base_tracking_);
  base_strain_ = system.box().strain();
  u.resize(n, Vec3::Zero());
  for (auto* v : {&gradient_, &gradient_trial_, &trial_, &direction_}) v->resize(n);
  relief_.assign(drag.size(), 0.5);
  damping_ = 0.0;

  // Φ(0), to compare the guess with and for `energies`. A zero guess is that
  // very point (AQS after a plastic event or a list rebuild): it is not
  // evaluated twice.
  Value value{}, trial_value{};
  const bool at_origin = is_origin(u);
  double phi_start = 0.0;
  if (at_origin || settings_.compare_guess || energies) {
    origin_.assign(n, Vec3::Zero());
    if (!evaluate_at(system, proximal, drag, h, origin_, value, gradient_, sliding_)) {
      result.list_invalid = true;
      return result;
    }
    phi_start = value.elastic + value.proximal + value.dissipation;
  }
  if (!at_origin) {
    Value guess{};
    if (!evaluate_at(system, proximal, drag, h, u, guess, gradient_, sliding_)) {
      result.list_invalid = true;
      return result;
    }
    // A guess worse than no move at all is dropped.
    if (settings_.compare_guess && guess.elastic + guess.proximal + guess.dissipation > phi_start) {
      std::fill(u.begin(), u.end(), Vec3::Zero());
      evaluate_at(system, proximal, drag, h, u, value, gradient_, sliding_);
    } else {
      value = guess;
    }
  }
  if (energies) energies->assign(1, value.elastic + value.proximal + value.dissipation - phi_start);
  double last_gnorm = 0.0;  // ‖g‖₂ at the last iteration
  double last_newton_move = 0.0;  // of the last iteration, if a full undamped step; else 0

  for (int it = 0;; ++it) {
    const ContactField& field = system.forces();
    const double mean_force =
        field.contact_count > 0 ? field.force_magnitude_sum / double(field.contact_count) : 1.0;
    double tolerance = settings_.relative_force * mean_force;
    if (settings_.absolute_force > 0.0)
      tolerance = settings_.loosen
                      ? std::max(tolerance, std::min(settings_.absolute_force,
                                                     kLoosestRelativeForce * mean_force))
                      : std::min(tolerance, settings_.absolute_force);
    result.residual = max_norm(gradient_);
    if (result.residual <= tolerance) {
      result.converged = true;
      break;
    }
    if (it >= max_iterations) break;
    ++result.iterations;
    ++counters_.iterations;

    // Inexact Newton direction (forcing term → 0 as the gradient falls).
    assemble(system, proximal, drag, h, tolerance);
    const double gnorm = std::sqrt(dot(gradient_, gradient_));
    const double eta =
        it == 0 ? kMaxForcing
                : std::max(forcing_term(gnorm, last_gnorm, result.residual, tolerance),
                           displacement_floor(last_newton_move, settings_.move_tolerance));
    last_gnorm = gnorm;
    // Levenberg–Marquardt damping μ: raised after an iteration whose CG met
    // negative curvature (a plastic instability, or a contact's tangential
    // softening), lowered after a full Newton step whose model was convex, so
    // that near a minimum the step is pure Newton.
    const double longest = damped_newton_direction(proximal, eta);
    if (negative_curvature_ && settings_.stop_when_unstable) {
      result.unstable = true;
      result.convex_fraction = convex_fraction(proximal);
      break;
    }

    double t = 1.0;
    const LineSearch searched = line_search(system, proximal, drag, h, u, value, trial_value, t);
    if (searched == LineSearch::list_invalid) {
      result.list_invalid = true;
      return result;
    }
    if (searched == LineSearch::failed) break;
    // Majoriser for contacts whose |w| shrinks fast (see the header).
    for (std::size_t k = 0; k < drag.size(); ++k) {
      relief_[k] = sliding_trial_.speed[k] >= 0.9 * sliding_.speed[k] ? 0.5 : 0.0;
    }
    const bool undamped = damping_ == 0.0;
    if (t == 1.0 && !negative_curvature_)
      damping_ = damping_ < 1e-8 * diagonal_scale_ ? 0.0 : 0.1 * damping_;
    u.swap(trial_);
    gradient_.swap(gradient_trial_);
    std::swap(sliding_, sliding_trial_);
    value = trial_value;
    if (energies)
      energies->push_back(value.elastic + value.proximal + value.dissipation - phi_start);
    const double move = t * longest;
    if (t == 1.0 && undamped) {
      if (settings_.move_tolerance > 0.0 &&
          within_move_tolerance(move, last_newton_move, settings_.move_tolerance)) {
        result.residual = max_norm(gradient_);
        result.converged = true;
        break;
      }
      last_newton_move = move;
    } else {
      last_newton_move = 0.0;
    }
    if (hopeless && hopeless(u, move)) {
      result.abandoned = true;
      break;
    }
  }
  return result;
}

}  // namespace softglass::micro
