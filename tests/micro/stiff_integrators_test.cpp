// The stiff-regime integrator (`implicit`, backward Euler as a minimising
// movement) and quasi-static shear (AQS): agreement with the explicit scheme
// where both work, first-order convergence, stability at γ̃ = 1e-11, and the
// monotone energy descent of the minimiser (docs/integrators.md).
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.h"
#include "micro/dynamics/incremental_minimiser.h"
#include "micro/protocol/aqs.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

// One small packing for every test (N = 256, φ = 0.8, seth2011), made once.
const Packing& small_packing() {
  static const Packing packing = [] {
    PackingSpec spec;
    spec.particles = 256;
    spec.volume_fraction = 0.8;
    spec.seed = 3;
    return make_packing(spec, testing::named_law("seth2011"));
  }();
  return packing;
}

struct Window {
  double sigma = 0.0, n1 = 0.0, n2 = 0.0;
  std::size_t steps = 0;
  Eigen::Matrix3d last = Eigen::Matrix3d::Zero();  // total stress at the end
};

// Shears the packing over `strain` with `spec` at γ̃, sampling the total stress
// every 0.005 strain; returns the means.
Window shear_window(const IntegratorSpec& spec, double gamma_tilde, double strain) {
  const Packing& packing = small_packing();
  ShearModel model;
  model.gamma_tilde = gamma_tilde;
  OverdampedShear flow(
      ContactSystem(packing.particles, packing.box, testing::named_law("seth2011"), 0.6), model);
  const auto integrator = make_integrator(spec);
  const double sample = 0.005;
  Window w;
  int samples = 0;
  double next = sample;
  flow.sample_stress_from(next - 1e-12);
  while (flow.strain() < strain - 1e-12) {
    integrator->step(flow, next - flow.strain());
    if (flow.strain() >= next - 1e-12) {
      const Eigen::Matrix3d total = flow.stress().total();
      const ShearObservables o = observables(total);
      w.sigma += o.shear, w.n1 += o.n1, w.n2 += o.n2, ++samples;
      w.last = total;
      next += sample;
      flow.sample_stress_from(next - 1e-12);
    }
  }
  w.sigma /= samples, w.n1 /= samples, w.n2 /= samples;
  w.steps = integrator->stats().accepted;
  return w;
}

TEST(StiffIntegrators, RegisteredByName) {
  const auto names = integrators().names();
  EXPECT_NE(std::find(names.begin(), names.end(), "implicit"), names.end());
  EXPECT_EQ(make_integrator({.name = "implicit"})->name(), "implicit");
  IntegratorSpec bad;
  bad.solver_tolerance = 0.1;
  EXPECT_THROW(bad.validate(), InputError);
}

// `auto` (the default) is the explicit scheme where it is accurate and cheap —
// at γ̃ ≥ kAutoImplicitBelow with the Stokes friction against the affine flow —
// and BDF2 elsewhere; it must be resolved before an integrator is made, and a
// zero tolerance becomes the chosen scheme's default.
TEST(StiffIntegrators, AutoPicksTheSchemeByRateAndStokesReference) {
  const IntegratorSpec spec;
  EXPECT_EQ(spec.name, "auto");
  EXPECT_THROW(make_integrator(spec), InputError);
  const IntegratorSpec fast = spec.resolved_for(kAutoImplicitBelow, StokesReference::affine);
  EXPECT_EQ(fast.name, "euler");
  EXPECT_EQ(fast.tolerance, default_tolerance("euler"));
  const IntegratorSpec slow = spec.resolved_for(0.5 * kAutoImplicitBelow, StokesReference::affine);
  EXPECT_EQ(slow.name, "bdf2");
  EXPECT_EQ(slow.tolerance, default_tolerance("bdf2"));
  EXPECT_EQ(make_integrator(slow)->name(), "bdf2");
  // Pair dashpots: every explicit step would solve a coupled velocity system.
  for (const double rate : {1e-9, kAutoImplicitBelow, 1e-2})
    EXPECT_EQ(spec.resolved_for(rate, StokesReference::neighbours).name, "bdf2") << rate;
  // A given tolerance is kept, and a named scheme is never replaced.
  IntegratorSpec given{.name = "euler", .tolerance = 3e-5};
  for (const auto stokes : {StokesReference::affine, StokesReference::neighbours}) {
    EXPECT_EQ(given.resolved_for(1e-9, stokes).name, "euler");
    EXPECT_EQ(given.resolved_for(1e-9, stokes).tolerance, 3e-5);
  }
}

// Where the explicit scheme is cheap (γ̃ = 1e-4) both integrate the same
// trajectory: at tight tolerances the window means agree to well within the
// 2 % accuracy target.
TEST(StiffIntegrators, ImplicitReproducesExplicitAtFastRate) {
  const Window explicit_run =
      shear_window({.name = "euler", .tolerance = 1e-5, .stability_fraction = 0.4}, 1e-4, 0.05);
  const Window implicit_run = shear_window({.name = "implicit", .tolerance = 1e-5}, 1e-4, 0.05);
  std::printf("[ measured ] sigma euler %.5e (%zu steps), implicit %.5e (%zu steps)\n",
              explicit_run.sigma, explicit_run.steps, implicit_run.sigma, implicit_run.steps);
  EXPECT_NEAR(implicit_run.sigma, explicit_run.sigma, 0.005 * explicit_run.sigma);
  const double scale = std::abs(explicit_run.sigma);
  EXPECT_NEAR(implicit_run.n1, explicit_run.n1, 0.01 * scale);
  EXPECT_NEAR(implicit_run.n2, explicit_run.n2, 0.01 * scale);
}

// The order under step refinement: with the step fixed (max step h dividing
// the sampling interval, a tolerance that never binds), the error of the stress
// at the end of a smooth window against a run at h/64, at h = 5e-3, 2.5e-3 and
// 1.25e-3 strain (γ̃ = 1e-4, where the window is smooth).
std::vector<double> refinement_orders(const std::string& scheme) {
  const double strain = 0.02, gamma_tilde = 1e-4;
  const auto at = [&](double h) {
    IntegratorSpec spec{.name = scheme, .tolerance = 0.1, .max_step = h};
    spec.solver_tolerance = 1e-12;
    return shear_window(spec, gamma_tilde, strain).last(1, 0);
  };
  const double reference = at(0.005 / 64);
  std::vector<double> errors;
  for (double h : {0.005, 0.0025, 0.00125}) errors.push_back(std::abs(at(h) - reference));
  std::printf("[ measured ] %s: errors of sigma_yx at h = 5e-3, 2.5e-3, 1.25e-3: %.3e %.3e %.3e\n",
              scheme.c_str(), errors[0], errors[1], errors[2]);
  return {std::log2(errors[0] / errors[1]), std::log2(errors[1] / errors[2])};
}

// Backward Euler is first order: the error halves when h halves.
TEST(StiffIntegrators, FirstOrderUnderStepRefinement) {
  for (double order : refinement_orders("implicit")) {
    EXPECT_GT(order, 0.7);
    EXPECT_LT(order, 1.5);
  }
}

// BDF2 is second order: the error falls fourfold when h halves (measured 2.07,
// 2.03; the same without the EHD drag, so the drag frozen at x_n does not
// lower the order in this window).
TEST(StiffIntegrators, Bdf2SecondOrderUnderStepRefinement) {
  for (double order : refinement_orders("bdf2")) {
    EXPECT_GT(order, 1.6);
    EXPECT_LT(order, 2.5);
  }
}

// At γ̃ = 1e-11 (explicit: ~1e9 steps per strain) both implicit schemes run a
// window in a few hundred steps, with a finite, positive stress close to the
// quasi-static one.
TEST(StiffIntegrators, StableAtLowestRate) {
  const double strain = 0.05;
  std::vector<Window> slow;
  for (const std::string scheme : {"implicit", "bdf2"}) {
    slow.push_back(shear_window({.name = scheme, .tolerance = 3e-2}, 1e-11, strain));
    std::printf("[ measured ] %s at gamma~ 1e-11: sigma %.4e, %zu steps over %.2f strain\n",
                scheme.c_str(), slow.back().sigma, slow.back().steps, strain);
    EXPECT_TRUE(std::isfinite(slow.back().sigma));
    EXPECT_GT(slow.back().sigma, 0.0);
    EXPECT_LT(slow.back().steps, 2000u);
  }

  AqsSettings aqs;
  aqs.strain_step = 1e-3;
  aqs.strain = strain;
  aqs.min_stationary_strain = strain / 2;
  const Packing& packing = small_packing();
  const AqsResult r = aqs_flow_curve_point(
      ContactSystem(packing.particles, packing.box, testing::named_law("seth2011"), 0.6), aqs);
  double quasi_static = 0.0;
  for (std::size_t k = 4; k < r.series.size(); k += 5) quasi_static += r.series.elastic[k](1, 0);
  quasi_static /= double(r.series.size() / 5);
  std::printf("[ measured ] AQS over the same window: sigma %.4e\n", quasi_static);
  for (const Window& w : slow) EXPECT_NEAR(w.sigma, quasi_static, 0.1 * quasi_static);
}

// 300 AQS steps of 1e-3, the last 0.1 strain analysed.
AqsSettings short_aqs() {
  AqsSettings settings;
  settings.strain_step = 1e-3;
  settings.strain = 0.3;
  settings.min_stationary_strain = 0.1;
  return settings;
}

// AQS: within every strain step the minimiser lowers the energy monotonically,
// and the run yields a positive yield stress with plastic drops.
TEST(Aqs, EnergyFallsMonotonicallyAndYieldStressIsPositive) {
  const Packing& packing = small_packing();
  ContactSystem system(packing.particles, packing.box, testing::named_law("seth2011"), 0.6);
  const AqsSettings settings = short_aqs();
  // Beyond the rounding of the energy sum (E ≈ 0.03 E*R³ here; the minimiser
  // accepts a step whose change is below 64 ε |E| if it lowers the gradient).
  const double rounding = 1e-13;
  std::size_t checked = 0, increases = 0;
  double largest_rise = 0.0;
  const AqsResult r = run_aqs(system, settings, [&](const std::vector<double>& energies) {
    for (std::size_t k = 1; k < energies.size(); ++k, ++checked) {
      largest_rise = std::max(largest_rise, energies[k] - energies[k - 1]);
      if (energies[k] > energies[k - 1] + rounding) ++increases;
    }
  });
  std::printf("[ measured ] largest rise of the energy within a step: %.2e\n", largest_rise);
  std::printf(
      "[ measured ] AQS: %zu steps, %zu Newton iterations, %zu stress drops, sigma_y %.4e "
      "± %.1e, %.2f s\n",
      r.steps, r.minimiser.iterations, r.stress_drops, r.summary["sigma"].mean,
      r.summary["sigma"].standard_error, r.seconds);
  EXPECT_GT(checked, r.steps);  // at least one iteration per step on average
  EXPECT_EQ(increases, 0u);
  EXPECT_EQ(r.unconverged_steps, 0u);
  EXPECT_GT(r.stress_drops, 5u);
  EXPECT_GT(r.summary["sigma"].mean, 0.0);
  EXPECT_EQ(r.summary["sigma_viscous"].mean, 0.0);
}

// A thin neighbour-list skin (0.2 R: a particle may move 0.1 R before a
// rebuild, as far as one Newton step may move it) must not stall the
// minimiser: a trial step beyond the list's reach is shortened, and a rebuild
// happens only once the accepted point has used up part of the reach.
TEST(Aqs, ThinNeighbourSkinStillConvergesEveryStep) {
  const Packing& packing = small_packing();
  ContactSystem system(packing.particles, packing.box, testing::named_law("seth2011"), 0.2);
  const AqsResult r = run_aqs(system, short_aqs());
  std::printf("[ measured ] skin 0.2: %zu steps, %zu Newton iterations, %zu unconverged\n", r.steps,
              r.minimiser.iterations, r.unconverged_steps);
  EXPECT_EQ(r.unconverged_steps, 0u);
  EXPECT_GT(r.stress_drops, 5u);
}

// The minimiser itself: on an affinely sheared packing, Φ = E falls at every
// Newton iteration and the residual reaches the tolerance.
TEST(IncrementalMinimiser, ConvergesWithMonotoneEnergy) {
  const Packing& packing = small_packing();
  ContactSystem system(packing.particles, packing.box, testing::named_law("seth2011"), 0.6);
  system.ensure_neighbours(0.1, 0.01);
  system.shear(0.01);
  IncrementalMinimiser minimiser({.relative_force = 1e-10});
  std::vector<Vec3> u;
  std::vector<double> energies;
  const IncrementalResult r = minimiser.minimise(system, {}, {}, 1.0, u, &energies);
  ASSERT_TRUE(r.converged);
  EXPECT_LT(energies.back(), 0.0);  // Φ = E here (no friction, no drag)
  for (std::size_t k = 1; k < energies.size(); ++k) EXPECT_LE(energies[k], energies[k - 1] + 1e-13);
  EXPECT_LT(force_residual(system.forces()), 1e-9);
  // The guess is the origin, where Φ is evaluated on entry: not a second time.
  // Then one evaluation per line-search trial.
  const IncrementalCounters& c = minimiser.counters();
  EXPECT_EQ(c.solves, 1u);
  EXPECT_EQ(c.force_evaluations, 1 + c.iterations + c.backtracks);
}

// The displacement stopping rule: a solve stopped by it is as close to the
// tightly converged minimiser as it promises (the rest of the solve would move
// no particle by more than move_tolerance), and is stopped sooner. The problem
// is an implicit step's: a proximal term ζ/h per particle on the affinely
// sheared packing.
TEST(IncrementalMinimiser, MoveToleranceBoundsTheDistanceToTheMinimiser) {
  const Packing& packing = small_packing();
  const auto solve = [&](const IncrementalSettings& settings, IncrementalCounters& counters) {
    ContactSystem system(packing.particles, packing.box, testing::named_law("seth2011"), 0.6);
    system.ensure_neighbours(0.1, 0.01);
    system.shear(0.01);
    const std::vector<double> proximal(system.size(), 1e-2);
    IncrementalMinimiser minimiser(settings);
    std::vector<Vec3> u;
    const IncrementalResult r = minimiser.minimise(system, proximal, {}, 1.0, u);
    EXPECT_TRUE(r.converged);
    counters = minimiser.counters();
    return system.wrapped_in_label_order().position;
  };
  IncrementalCounters tight, stopped;
  const auto reference = solve({.relative_force = 1e-12}, tight);
  for (const double tolerance : {1e-3, 1e-4, 1e-5}) {
    const auto x = solve({.relative_force = 1e-12, .move_tolerance = tolerance}, stopped);
    double distance = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a)
      distance = std::max(distance, (x[a] - reference[a]).norm());
    std::printf("[ measured ] move tolerance %.0e: %zu of %zu Newton iterations, distance %.2e\n",
                tolerance, stopped.iterations, tight.iterations, distance);
    EXPECT_LE(distance, tolerance);
    EXPECT_LT(stopped.iterations, tight.iterations);
  }
}

// The instability stop of the implicit step (IncrementalSettings::
// stop_when_unstable). The packing is sheared quasi-statically until a strain
// step whose minimisation meets non-positive curvature (a plastic event: the
// damped minimiser raises its damping). The same problem with a proximal term
// far below the Hessian's scale (an implicit step much longer than the
// relaxation time) stops with `unstable`: at a point no worse than the guess,
// with a convex fraction in (0, 1] — the step at which the proximal term
// would make the curvature along CG's direction vanish, here well below 1.
// With a proximal term far above the contact stiffnesses (a step much shorter
// than the relaxation time) Φ is convex and the solve converges.
TEST(IncrementalMinimiser, StopsWhereTheStepIsUnstable) {
  const Packing& packing = small_packing();
  ContactSystem system(packing.particles, packing.box, testing::named_law("seth2011"), 0.6);
  IncrementalMinimiser aqs({.relative_force = 1e-9});
  std::vector<Vec3> u;
  ContactSystem before = system;
  for (int step = 0; step < 500; ++step) {
    system.ensure_neighbours(0.1, system.box().strain() + 1e-3);
    system.shear(1e-3);
    before = system;
    const std::size_t raises = aqs.counters().damping_raises;
    u.assign(system.size(), Vec3::Zero());
    aqs.minimise(system, {}, {}, 1.0, u);
    if (aqs.counters().damping_raises > raises) break;
  }
  ASSERT_GT(aqs.counters().damping_raises, 0u) << "no plastic event in 0.5 strain";

  const auto solve = [&](double proximal_value, std::vector<double>* energies) {
    ContactSystem at = before;
    IncrementalMinimiser minimiser({.relative_force = 1e-9, .stop_when_unstable = true});
    std::vector<Vec3> from_origin(at.size(), Vec3::Zero());
    return minimiser.minimise(at, std::vector<double>(at.size(), proximal_value), {}, 1.0,
                              from_origin, energies);
  };
  std::vector<double> energies;
  IncrementalResult r = solve(1e-12, &energies);
  std::printf("[ measured ] unstable after %d Newton iterations, convex fraction %.3g\n",
              r.iterations, r.convex_fraction);
  EXPECT_TRUE(r.unstable);
  EXPECT_FALSE(r.converged);
  EXPECT_LE(energies.back(), 0.0);  // Φ relative to the guess (the origin)
  EXPECT_GT(r.convex_fraction, 0.0);
  EXPECT_LT(r.convex_fraction, 1e-3);
  r = solve(1e3, nullptr);  // E* R against stiffnesses ≲ 1
  EXPECT_TRUE(r.converged);
  EXPECT_FALSE(r.unstable);
}

}  // namespace
}  // namespace softglass::micro
