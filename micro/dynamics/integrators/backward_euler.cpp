// `implicit`: backward Euler as a minimising movement, with a local error
// estimate and step-size control, and `bdf2`, its variable-step second-order
// sibling (the default below γ̃ = 1e-5). For the stiff regime (low γ̃).
//
// Why these schemes. The explicit step is bounded by the fastest contact
// relaxation, 2/λ ∝ γ̃ (overdamped_shear.h), whatever the accuracy needed. The
// motion is a generalised gradient flow (incremental_minimiser.h), and backward
// Euler for such a flow is the minimisation of energy + dissipation over one
// step: unconditionally stable and energy-decreasing (L-stable on the linear
// part: fast modes are damped out, not just bounded), so the step is limited by
// accuracy only. Between plastic events the motion at low γ̃ is quasi-static —
// the particles follow a slowly moving energy minimum — and steps are limited by
// max_step; an event relaxes on the time scale η_s/E*, i.e. a strain ∝ γ̃, and
// the error control shrinks the step to resolve it in a number of steps that
// does not depend on γ̃. Most steps are spent inside events, on accuracy, which
// is what a second order buys: variable-step BDF2,
//     d_{n+1} = c d_n + βh v(x_{n+1}),  c = ω²/(1 + 2ω),  β = (1 + ω)/(1 + 2ω),
// with d the step's non-affine move and ω = h_n/h_{n−1}, is the same
// minimisation with the base point moved by c d_n and the step βh (A- and
// L-stable, zero-stable for ω < 1 + √2; it does not guarantee the energy
// decrease of backward Euler). Runge–Kutta–Chebyshev (stabilised explicit)
// would still need ∝ √(λh) stages per step, a cost per strain growing like
// γ̃^{-1/2}.
//
// Step. From x_n with velocities v_n (the last step's u/h): x⁰ = x_n sheared
// affinely by the drive's strain increment Δγ over h (h itself in steady
// shear), plus ½hΔγ v_{n,y} e_x (the affine advection of the particles' own
// y-motion over the step, to second order); the frozen drag sees the affine
// flow's rate at the step's end (shear_drive.h); then u = argmin Φ, starting
// from the guess u = h v_n; x_{n+1} = x⁰ + u, and the flow is evaluated there
// (forces, EHD velocities, stress), which the caller and the next step read.
//
// Error. Backward Euler's local error is −½h² ẍ; with v_{n+1} ≈ u/h (the
// backward-Euler velocity, the ODE's at x_{n+1}) and v_n the previous step's
// u/h, e = ½|u − h v_n| per particle (the difference between the implicit step
// and the explicit predictor x_n + h v_n; ½h²|ẍ| to leading order). Both
// velocities are on the slow manifold — each backward-Euler point satisfies the
// equation of motion — so the estimate is not polluted by the stiff modes (the
// estimate ½h|v(x_{n+1}) − v(x_n)| of an explicit step would be). v_n is the
// step's u/h rather than the velocity solved at x_n: that solve (the EHD drag
// and pair dashpots at x_n, a nonlinear system) cost about a quarter of the
// run, and nothing else needs it between the stress samples, where it still
// runs (OverdampedShear::accept_step_velocities). The step is
// accepted when max_α e_α ≤ tolerance (units of R); the next step is
// h · min(1.5, max(0.2, 0.9 √(tol/e))) (size_factor says why). A step whose
// solve meets non-positive curvature spans a plastic instability faster than
// the step can follow (λh ≥ 1 along an unstable mode of rate λ): it is
// rejected at once, before any Newton move, and retried shorter (see the
// `unstable` branch). A step whose nonlinear solve fails is retried with h/4.
// BDF2 (Formula below) starts from the second-order predictor
// h v_n + ½h²(v_n − v_{n−1})/h_{n−1}, and turns its distance to the solution
// into the local error by Milne's device; its first step, and a step more than
// twice the last, is a backward-Euler one.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "common/errors.h"

#include "micro/dynamics/incremental_minimiser.h"
#include "micro/dynamics/integrator.h"

namespace softglass::micro {
namespace {

double min_radius(const std::vector<double>& radius) {
  return *std::min_element(radius.begin(), radius.end());
}

// Non-affine move per step (units of R) that the neighbour list is made valid
// for at most (and at most 0.3 skin, leaving room for the strain).
constexpr double kWidestMargin = 0.2;

// Largest step ratio h_{n+1}/h_n at which a step is taken with BDF2; a larger
// one (after a step cut short to land on a sample) is taken with backward Euler.
// Variable-step BDF2 is zero-stable for ratios below 1 + √2.
constexpr double kMaxBdf2Ratio = 2.0;

// Largest growth of the step after an accepted one. With 2, 28 % of the steps
// that grew were rejected next (N = 1000, φ = 0.80, γ̃ = 1e-9, 5 strain, mean
// growth 1.56): the error rises faster than the controller's model as an
// event starts.
constexpr double kMaxGrowth = 1.5;

class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(const IntegratorSpec& spec, int order) : spec_(spec), order_(order) {
    IncrementalSettings s;
    s.relative_force = spec.solver_tolerance;
    s.compare_guess = false;  // the guess is the predictor
    s.stop_when_unstable = true;  // instead of damping through an instability
    minimiser_.set_settings(s);
  }

  std::string name() const override { return order_ == 2 ? "bdf2" : "implicit"; }

  double step(OverdampedShear& flow, double max_step) override {
    // The frozen drag of a step holds pair films only, and the reservoir
    // friction against the affine flow: with walls the step would drop the
    // wall films' drag (contact/wall_contacts.h) and the solvent's mean flow
    // (model/solvent_flow.h).
    if (flow.system().walls().present() || !flow.solvent_flow().affine())
      throw InputError(
          "integrator 'implicit' does not carry the wall films: with walls use "
          "scheme = euler");
    if (!flow.evaluated()) flow.evaluate();
    double h = std::min({proposal_, spec_.max_step, max_step});
    ContactSystem& system = flow.system();
    const double gamma_tilde = flow.model().gamma_tilde;
    double list_margin = 0.0;
    bool rejected = false;
    const double widest = std::min(kWidestMargin, 0.3 * system.neighbours().skin());
    std::optional<FrozenAt> frozen;  // what drag_ holds, once frozen in this call

    for (int attempt = 0;; ++attempt) {
      if (attempt > 200) throw NumericalError("implicit step: no acceptable step size");
      // List valid for the predicted move (twice the explicit predictor, at
      // least 0.02 R); a solve that leaves it restarts with a larger margin.
      const double predicted = std::min(std::max(2.0 * h * flow.max_speed(), 0.02), widest);
      system.ensure_neighbours(std::max(predicted, list_margin), flow.strain_after(h));
      flow.save(before_);
      const std::size_t n = system.size();
      const auto& p = system.particles();

      // Frozen drag from the contacts at x_n. A retry after a rejection starts
      // from the same x_n (restored), so the drag is kept unless the list was
      // rebuilt (which reorders the particles) or the drive's rate at the step's
      // end moved with h (oscillatory shear): see FrozenAt.
      const ShearModel& model = flow.model();
      const FrozenAt at{system.neighbours().builds(), system.box().image_offset(),
                        flow.drive().rate(flow.time() + h)};
      if (!frozen || !frozen->same(at)) {
        freeze(system, model, gamma_tilde, at.rate);
        frozen = at;
      }
      const FrozenDrag& drag = drag_;
      const Formula f = formula(h);
      const double hs = f.beta * h;  // the solve's step: u = βh v_{n+1}
      proximal_.resize(n);
      velocity_.assign(p.velocity.begin(), p.velocity.end());  // v_n
      predicted_.resize(n);
      shift_.resize(n);
      const double strain_step = flow.strain_increment(h);
      for (std::size_t a = 0; a < n; ++a) {
        proximal_[a] = model.drag.stokes.reservoir(friction_[a]) / hs;
        // The step's non-affine move is d_{n+1} = c d_n + u. The unknown u
        // starts from the predictor h v_n (+ ½h²(v_n − v_{n−1})/h_{n−1} for
        // BDF2) less c d_n; the base point x⁰ is x_n sheared plus, as a
        // velocity over h, the advection term and c d_n.
        Vec3 move = h * velocity_[a];
        Vec3 shift(0.5 * strain_step * velocity_[a].y(), 0.0, 0.0);
        if (f.order == 2) {
          const std::uint32_t label = p.label[a];
          move += (0.5 * h * h / last_h_) * (velocity_[a] - last_velocity_[label]);
          move -= f.c * last_move_[label];
          shift += (f.c / h) * last_move_[label];
        }
        predicted_[a] = move;
        shift_[a] = shift;
      }
      guess_.assign(predicted_.begin(), predicted_.end());
      // x⁰: affine shear by Δγ plus shift_ (above).
      flow.advance_affinely(h);
      system.move(h, shift_);
      // The solve's residual g moves a particle by at most g h/ζ (the proximal
      // term bounds the Hessian below): 1 % of the step tolerance is enough.
      // With the friction against the neighbours ζ is the reservoir's share
      // alone (1 %) and that bound 100× too cautious for any motion but a
      // uniform translation; so the solve also stops once Newton's rate says
      // that it would move no particle by more than a tenth of the step
      // tolerance (CVODE's fraction). That saves Newton and CG iterations at
      // the lowest rates and moves σ, N1, N2 by far less than their scatter
      // (docs/integrators.md, "Stopping the Newton iteration"; measured in
      // bench/results/newton_stop-2026-11-27.md).
      IncrementalSettings settings = minimiser_.settings();
      settings.absolute_force = 0.01 * spec_.tolerance *
                                model.drag.stokes.reservoir(model.friction(min_radius(p.radius))) /
                                hs;
      settings.loosen = true;
      settings.move_tolerance = 0.1 * spec_.tolerance;
      minimiser_.set_settings(settings);
      // An attempt that will be rejected is stopped early: once an iterate's
      // error exceeds the tolerance by more than the error constant times its
      // last move, the converged step would fail the test below too (the rest
      // of the solve moves a particle by less than the last iteration did —
      // Newton converges superlinearly — and the error is the constant times
      // the distance to the predictor). A fifth of the attempts are rejected,
      // most at the start of a plastic event, and each solved to the end cost
      // as much as an accepted one. The stopped attempt meets the same error
      // test below, from its partial error. (The bound subtracts the error
      // constant, ½ to 8/23, times the move, not the whole move, which was 2–3×
      // looser than the argument; bench/results/instability_stop-2026-11-28.md.)
      const auto hopeless = [&](const std::vector<Vec3>&, double move) {
        return step_error(f) - f.error_constant * move > spec_.tolerance;
      };
      const IncrementalResult r =
          minimiser_.minimise(system, proximal_, drag, hs, guess_, nullptr, -1, hopeless);
      stats_.minimiser = minimiser_.counters();
      if (r.list_invalid) {
        // The step moves particles further than the list allows. If the error
        // of the partial solution already exceeds the tolerance, the step
        // spans a rearrangement and is shortened; else, if the list was made
        // for a small move, it is rebuilt with a wider margin.
        flow.restore(before_);
        record_rejected(Rejection::list);
        rejected = true;
        const double partial = step_error(f);
        if (partial <= spec_.tolerance && std::max(predicted, list_margin) < 0.5 * widest) {
          list_margin = widest;
        } else {
          h *= partial > spec_.tolerance ? std::max(0.2, size_factor(partial)) : 0.25;
        }
        continue;
      }
      // The step spans an instability (λh ≥ 1 along CG's direction; see
      // stop_when_unstable): it cannot be accurate. Counted as an error
      // rejection, retried at half the step at which the proximal term would
      // make Φ convex along that direction (at least a twentieth of h).
      if (r.unstable) {
        flow.restore(before_);
        record_rejected(Rejection::error);
        rejected = true;
        h *= std::clamp(0.5 * r.convex_fraction, 0.05, 0.5);
        continue;
      }
      if (!r.converged && !r.abandoned) {
        flow.restore(before_);
        record_rejected(Rejection::solver);
        rejected = true;
        h *= 0.25;
        continue;
      }
      const double error = step_error(f);
      const double factor = size_factor(error);
      if (error > spec_.tolerance) {
        flow.restore(before_);
        record_rejected(Rejection::error);
        rejected = true;
        h *= std::max(0.2, factor);
        continue;
      }
      // Accepted: the step's velocity u/(βh) stands for the flow's at x_{n+1}
      // (solved there only where the stress is sampled; see the header). BDF2
      // keeps d_{n+1} and v_n by label (a list rebuild reorders particles).
      if (order_ == 2) remember(p.label, f, h);
      for (std::size_t a = 0; a < n; ++a) velocity_[a] = guess_[a] / hs;
      flow.accept_step_velocities(velocity_);
      record_accepted(h);
      // No growth right after a rejection (Hairer & Wanner, Solving ODEs II,
      // IV.8): the rejected size was too large a moment ago.
      const double growth = rejected ? 1.0 : kMaxGrowth;
      if (h < max_step || factor < 1.0) proposal_ = h * std::clamp(factor, 0.2, growth);
      return h;
    }
  }

 private:
  // What the frozen drag depends on besides x_n: the list build (whose
  // particle order friction_ and the contacts follow), the Lees–Edwards offset
  // (the contacts across the gradient boundary; a restore sets the strain from
  // a double, which could round it) and the rate. Compared bit for bit, so a
  // kept drag is the one a recomputation would give, to the last bit.
  struct FrozenAt {
    std::size_t build;
    double offset, rate;
    bool same(const FrozenAt& o) const {
      return build == o.build &&
             std::bit_cast<std::uint64_t>(offset) == std::bit_cast<std::uint64_t>(o.offset) &&
             std::bit_cast<std::uint64_t>(rate) == std::bit_cast<std::uint64_t>(o.rate);
    }
  };

  // friction_ and drag_ from the contacts where the system is (x_n).
  void freeze(ContactSystem& system, const ShearModel& model, double gamma_tilde, double rate) {
    const auto& p = system.particles();
    friction_.resize(system.size());
    for (std::size_t a = 0; a < system.size(); ++a) friction_[a] = model.friction(p.radius[a]);
    drag_.clear();
    if (model.drag.enabled || model.drag.stokes.has_pairs()) {
      ++stats_.drag_freezes;
      // At x_n, where the last accepted solve (or the stress sample after it)
      // evaluated the forces with their contacts: not evaluated again unless
      // the list was rebuilt since.
      const ContactField& field = system.current_forces({.contacts = true, .virial = false});
      freeze_drag(field.contacts, gamma_tilde, rate, model.drag, friction_, drag_);
    }
  }

  // The step's formula, d_{n+1} = c d_n + βh v_{n+1}: backward Euler (c = 0,
  // β = 1), or variable-step BDF2 with ω = h/h_{n−1},
  //     c = ω²/(1 + 2ω),  β = (1 + ω)/(1 + 2ω),
  // whose local error is −(1 + ω)²/(6ω(1 + 2ω)) h³ x⁽³⁾. `error_constant`
  // turns the distance between the solution and the predictor into that
  // error: ½ for backward Euler (predictor h v_n); for BDF2 the predictor
  // h v_n + ½h²(v_n − v_{n−1})/h_{n−1} is off by (2ω + 3)/(12ω) h³ x⁽³⁾, so
  // the error is 2(1 + ω)²/(6ω² + 12ω + 5) of the distance (8/23 at ω = 1).
  struct Formula {
    int order = 1;
    double c = 0.0, beta = 1.0, error_constant = 0.5;
  };
  Formula formula(double h) const {
    if (order_ == 1 || last_h_ <= 0.0 || h > kMaxBdf2Ratio * last_h_) return {};
    const double w = h / last_h_;
    return {2, w * w / (1.0 + 2.0 * w), (1.0 + w) / (1.0 + 2.0 * w),
            2.0 * (1.0 + w) * (1.0 + w) / (6.0 * w * w + 12.0 * w + 5.0)};
  }

  // The controller's factor 0.9 (tol/e)^{1/2} (2 for e = 0), for either
  // order. An error ∝ h^{p+1} would call for the exponent 1/3 with BDF2, but
  // from a rejected attempt to its retry (the same x_n, a smaller h) the error
  // fell like h^2.0 on average, not h^3 (27 000 retries; N = 1000, φ = 0.80,
  // γ̃ = 1e-9): the forces are not smooth on the step's scale (a film's drag
  // ∝ |w|^{1/2} as its sliding velocity passes through zero, contacts opening
  // and closing), so the local error behaves as a first-order one. With 1/3
  // a retry was cut too little and rejected again. Exponent 1/2 and the growth
  // cap kMaxGrowth: 7 % fewer Newton iterations in that run.
  double size_factor(double error) const {
    if (error <= 0.0) return 2.0;
    return 0.9 * std::sqrt(spec_.tolerance / error);
  }

  // The error constant × max_α |u_α − predicted_α| for the solution (or
  // partial solution) in guess_.
  double step_error(const Formula& f) const {
    double worst = 0.0;
    for (std::size_t a = 0; a < guess_.size(); ++a)
      worst = std::max(worst, (guess_[a] - predicted_[a]).squaredNorm());
    return f.error_constant * std::sqrt(worst);
  }

  // After an accepted step: d_{n+1} = c d_n + u and v_n, by label, and h.
  void remember(const std::vector<std::uint32_t>& labels, const Formula& f, double h) {
    const std::size_t n = labels.size();
    last_move_.resize(n);
    last_velocity_.resize(n);
    for (std::size_t a = 0; a < n; ++a) {
      const std::uint32_t label = labels[a];
      const Vec3 before = f.order == 2 ? Vec3(f.c * last_move_[label]) : Vec3::Zero();
      last_move_[label] = before + guess_[a];
      last_velocity_[label] = velocity_[a];
    }
    last_h_ = h;
  }

  IntegratorSpec spec_;
  int order_;  // 1: backward Euler; 2: BDF2 where the step ratio allows
  IncrementalMinimiser minimiser_;
  FrozenDrag drag_;
  std::vector<double> proximal_, friction_;
  std::vector<Vec3> velocity_, guess_, predicted_, shift_;
  // BDF2's history, by particle label: d_n and v_{n−1}; h_{n−1} (0: none).
  std::vector<Vec3> last_move_, last_velocity_;
  double last_h_ = 0.0;
  double proposal_ = 1e300;
  OverdampedShear::Snapshot before_;
};

std::unique_ptr<Integrator> make(const IntegratorSpec& spec) {
  return std::make_unique<BackwardEuler>(spec, 1);
}
std::unique_ptr<Integrator> make_bdf2(const IntegratorSpec& spec) {
  return std::make_unique<BackwardEuler>(spec, 2);
}
}  // namespace

// Cost (sweep planning): seconds_at_reference × (γ̃/1e-5)^rate_exponent per 5
// strain at N = 1000, fitted to one measured column
// (bench/results/sweep_cost_model-2026-11-30.md).
IntegratorEntry implicit_integrator() {
  return {"implicit",
          "backward Euler as a minimising movement, Newton-CG, error control (for low gamma~)",
          {},
          make,
          {.default_tolerance = 1e-3,
           .seconds_at_reference = 4.5,
           .rate_exponent = -0.55,
           .minimises = true}};
}

// The default below γ̃ = 1e-5, and at every rate with the Stokes friction
// between neighbours (`auto`). Tolerance 3e-3: as accurate as `implicit` at
// 1e-3 (docs/integrators.md, "BDF2"). Cost: a power law in γ̃ per 5 strain at
// N = 1000 with a floor (about a step per stress sample, each with its
// velocity solve), fitted to the rate cases of the whole `paper` sweep of the
// default model: least squares in logs over the low rates, the floor from the
// median of the highest. The model has no φ, so single cases scatter about it
// while the sweep's total, what the planner needs, follows it closely; the fit
// and its scatter are in bench/results/sweep_cost_model-2026-11-30.md.
IntegratorEntry bdf2_integrator() {
  return {"bdf2",
          "variable-step BDF2 as a minimising movement, Newton-CG, error control (for low gamma~)",
          {},
          make_bdf2,
          {.default_tolerance = 3e-3,
           .seconds_at_reference = 1.42,
           .rate_exponent = -0.484,
           .floor_seconds = 2.33,
           .minimises = true}};
}

}  // namespace softglass::micro
