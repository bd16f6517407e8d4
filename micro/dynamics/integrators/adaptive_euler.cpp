// `euler`: explicit Euler with a step that follows the stiffness and a local
// error estimate.
//
// Step size. dt = min(stability_fraction · 2/λ, error-controlled step, max_step),
// where λ is the Gershgorin bound on the fastest elastic relaxation rate
// (overdamped_shear.h). Since λ bounds every eigenvalue of the linearised
// dynamics, dt λ < 2 keeps explicit Euler stable whatever γ̃ is.
//
// Error. The difference between the Euler step and Heun's second-order step from
// the same point is  e = (dt/2)|u(x_{n+1}) − u(x_n)|, and u(x_{n+1}) is what the
// next step needs anyway, so the estimate costs nothing. A step whose largest
// per-particle e exceeds the tolerance is rejected and retried smaller; the next
// step is dt·min(2, 0.9 √(tol/e)) (Euler's local error is O(dt²)).
#include <algorithm>
#include <cmath>

#include "micro/dynamics/integrator.h"
#include "micro/numerics/vector_clones.h"

namespace softglass::micro {
namespace {

class AdaptiveEuler final : public Integrator {
 public:
  explicit AdaptiveEuler(const IntegratorSpec& spec) : spec_(spec) {}

  std::string name() const override { return "euler"; }

  double step(OverdampedShear& flow, double max_step) override {
    if (!flow.evaluated()) flow.evaluate();
    const double stable = spec_.stability_fraction * 2.0 / std::max(flow.relaxation_rate(), 1e-300);
    double dt = std::min({proposal_, stable, spec_.max_step, max_step});

    for (;;) {
      flow.prepare_step(dt);
      const double strain_step = flow.strain_increment(dt);
      flow.save_and_step(before_, dt);
      flow.evaluate();
      const double error = error_estimate(before_.velocity, flow, dt, strain_step);
      const double factor = error > 0.0 ? 0.9 * std::sqrt(spec_.tolerance / error) : 2.0;
      if (error <= spec_.tolerance) {
        record_accepted(dt);
        // A step cut short by max_step says nothing about the step the error allows.
        if (dt < max_step || factor < 1.0) proposal_ = dt * std::min(2.0, factor);
        return dt;
      }
      flow.restore(before_);
      record_rejected(Rejection::error);
      dt *= std::max(0.2, factor);
    }
  }

 private:
  // max_α (dt/2)|u_α(x_{n+1}) − u_α(x_n)| for the non-affine velocity and the
  // advection of y by the affine flow: u = c y e_x + v, and y changed by dt v_y
  // while the cell sheared by Δγ (the drive's own change of c moves every
  // particle affinely, which the step integrates exactly).
  SOFTGLASS_VECTOR_CLONES static double error_estimate(const std::vector<Vec3>& v_before,
                                                       const OverdampedShear& flow, double dt,
                                                       double strain_step) {
    const auto v_after = flow.velocities();
    // Componentwise: a Vec3 built and then changed in one component goes
    // through memory, and its reload stalled this loop (11 % of a Hertz step).
    double worst = 0.0;
#pragma omp simd reduction(max : worst)
    for (std::size_t a = 0; a < v_before.size(); ++a) {
      const Vec3& before = v_before[a];
      const Vec3& after = v_after[a];
      const double cx = after.x() - before.x() + strain_step * before.y();
      const double cy = after.y() - before.y(), cz = after.z() - before.z();
      worst = std::max(worst, cx * cx + cy * cy + cz * cz);
    }
    return 0.5 * dt * std::sqrt(worst);
  }

  IntegratorSpec spec_;
  double proposal_ = 1e300;
  OverdampedShear::Snapshot before_;  // the state a rejected step returns to
};

std::unique_ptr<Integrator> make(const IntegratorSpec& spec) {
  return std::make_unique<AdaptiveEuler>(spec);
}
}  // namespace

// Cost (sweep planning): 25 s per 5 strain at N = 1000, γ̃ = 1e-5, steps per
// strain ∝ γ̃^-0.8 below (docs/sweeps.md, docs/validation.md).
IntegratorEntry euler_integrator() {
  return {"euler",
          "explicit Euler with error control, step below the stability limit (cost ~ 1/gamma~)",
          {},
          make,
          {.default_tolerance = 1e-4, .seconds_at_reference = 25.0, .rate_exponent = -0.8}};
}

}  // namespace softglass::micro
