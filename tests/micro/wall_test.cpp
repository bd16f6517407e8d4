// Particles against smooth walls (issue 21): the wall contact is the pair
// contact with R_β → ∞ (contact/wall_contacts.h), its film the pair film with
// R_c = R_α (model/wall_films.h), and a wall run balances forces
// (analysis/wall_sample.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "common/errors.h"
#include "micro/analysis/wall_sample.h"
#include "micro/dynamics/integrator.h"
#include "micro/packing/wall_packing.h"
#include "micro/protocol/wall_run.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

using testing::named_law;

constexpr double kSide = 20.0, kSkin = 0.6;
const Walls kWalls{3.0, 17.0};  // slab 6 R ≥ 2 (R_max + skin) for R ≤ 2.4

ContactSystem one_particle(const Vec3& x, double radius, const std::string& law = "piecewise") {
  ContactSystem system(Particles({x}, {radius}), LeesEdwardsBox(kSide), named_law(law), kSkin);
  system.set_walls(kWalls);
  return system;
}

// The contact law's force with R_c = R_α, normal to the wall, both walls; and
// its energy. Exact: the same law object, evaluated at the same ε.
TEST(WallContact, PressedParticleFeelsTheContactLawWithItsOwnRadius) {
  // Dyadic radius and overlaps: the positions hold them exactly, so the code's
  // ε = h/R_α is the test's to the last bit. Each branch of the default law.
  const double radius = 1.25;
  for (const double h : {0.0625, 0.375, 0.75, 1.125}) {
    const double eps = h / radius;
    for (const bool lower : {true, false}) {
      const double y = lower ? kWalls.lower + radius - h : kWalls.upper - radius + h;
      ContactSystem system = one_particle(Vec3(5.0, y, 7.0), radius);
      const ContactField& field = system.compute_forces({.energy = true});
      const double expected = radius * radius * system.law().force(eps);
      ASSERT_EQ(field.walls.size(), 1u);
      EXPECT_DOUBLE_EQ(field.force[0].y(), lower ? expected : -expected);
      EXPECT_EQ(field.force[0].x(), 0.0);
      EXPECT_EQ(field.force[0].z(), 0.0);
      EXPECT_DOUBLE_EQ(field.energy, radius * radius * radius * system.law().energy(eps));
      EXPECT_DOUBLE_EQ(field.walls.deformation[0], eps);
      EXPECT_EQ(field.contact_count, 0u);  // walls are not pairs
    }
  }
  // Out of reach: no contact.
  ContactSystem apart = one_particle(Vec3(5.0, kWalls.lower + 1.2001, 7.0), 1.2);
  EXPECT_EQ(apart.compute_forces().walls.size(), 0u);
}

// Energy and force agree (central differences of E along y) for particles at
// both walls, across the law's branches.
TEST(WallContact, ForceIsMinusTheEnergyGradient) {
  const double radius = 0.93;
  for (const double y : {kWalls.lower + 0.9, kWalls.lower + 0.6, kWalls.lower + 0.2,
                         kWalls.upper - 0.5, kWalls.upper - 0.05}) {
    const double step = 1e-6;
    const auto energy = [&](double at) {
      ContactSystem s = one_particle(Vec3(4.0, at, 4.0), radius);
      return s.compute_forces({.energy = true}).energy;
    };
    ContactSystem s = one_particle(Vec3(4.0, y, 4.0), radius);
    const double force = s.compute_forces().force[0].y();
    const double derivative = (energy(y + step) - energy(y - step)) / (2.0 * step);
    // Central differences: error ~ step² E''' plus rounding ~ 1e-16 E / step.
    EXPECT_NEAR(-derivative, force, 1e-7 * std::max(1.0, std::abs(force))) << "y = " << y;
  }
}

// A particle sliding on the lower wall at a known load: the film drag is
// a √|w| against w = v + c (y − y_w) e_x with a = (¾ γ̃ R |f| √ε)^{1/2}.
TEST(WallFilm, SlidingParticleFeelsTheEhdDragOfItsLoad) {
  const double radius = 1.05, eps = 0.2, gamma_tilde = 1e-5, rate = 1.0;
  const double y = kWalls.lower + radius * (1.0 - eps);
  ContactSystem system = one_particle(Vec3(5.0, y, 5.0), radius);
  const ContactField& field = system.compute_forces();
  const double load = radius * radius * system.law().force(eps);
  const double a = std::sqrt(0.75 * gamma_tilde * radius * load * std::sqrt(eps));
  const EhdDrag drag(EhdSettings{});
  const std::vector<Vec3> v{Vec3(-0.3, 0.7, 0.4)};  // the normal part slides nothing
  std::vector<Vec3> per_film(1);
  drag.wall_drag(field.walls, gamma_tilde, rate, v, per_film);
  const Vec3 w(-0.3 + rate * (y - kWalls.lower), 0.0, 0.4);
  const Vec3 expected = -a * std::sqrt(w.norm()) * w.normalized();
  EXPECT_NEAR((per_film[0] - expected).norm(), 0.0, 1e-14 * expected.norm());

  // The velocity solve: a particle pushed along x by F against its Stokes
  // friction and the wall film. ζ v + a √(v + c d) = F in 1D (v + c d > 0),
  // solved here by bisection.
  const double zeta = 6.0 * std::numbers::pi * gamma_tilde * radius / 0.01;
  const double push = 3.0 * a;
  std::vector<Vec3> force{Vec3(push, 0.0, 0.0)}, solved{Vec3::Zero()};
  EhdDrag solver(EhdSettings{.tolerance = 1e-12});
  solver.solve(ContactList{}, gamma_tilde, rate, std::vector<double>{zeta}, force, solved,
               field.walls);
  const double d = y - kWalls.lower;
  double low = -rate * d, high = push / zeta;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (low + high);
    (zeta * mid + a * std::sqrt(mid + rate * d) < push ? low : high) = mid;
  }
  EXPECT_NEAR(solved[0].x(), low, 1e-9 * std::abs(low));
  EXPECT_NEAR(solved[0].z(), 0.0, 1e-12);
}

TEST(WallInput, RefusesWallsThatLeaveNoEmptySlabOrLeaveTheCell) {
  ContactSystem system(Particles({Vec3(5, 10, 5)}, {1.0}), LeesEdwardsBox(kSide),
                       named_law("hertz"), kSkin);
  // slab 20 − 18.5 + 1 = 2.5 < 2 (1 + 0.6)·… = 3.2
  EXPECT_THROW(
      {
        try {
          system.set_walls({1.0, 18.5});
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("walls"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  EXPECT_THROW(system.set_walls({-1.0, 10.0}), InputError);
  EXPECT_THROW(system.set_walls({5.0, 25.0}), InputError);
}

TEST(WallInput, RefusesTooSmallAGapAndVolumeFractionsOutOfRange) {
  PackingSpec spec;
  spec.particles = 20;  // a gap below two diameters at φ = 0.8
  EXPECT_THROW(
      {
        try {
          make_wall_packing(spec, named_law("piecewise"));
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("gap"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  spec.particles = 200;
  spec.volume_fraction = 0.5;
  EXPECT_THROW(make_wall_packing(spec, named_law("piecewise")), InputError);
}

// A packing between walls sits at its φ of the slab, force-balanced with the
// wall forces included.
TEST(WallPacking, IsRelaxedAtTheSlabVolumeFraction) {
  PackingSpec spec;
  spec.particles = 150;
  spec.volume_fraction = 0.8;
  const WallPacking p = make_wall_packing(spec, named_law("piecewise"));
  EXPECT_TRUE(p.packing.report.converged);
  EXPECT_NEAR(p.packing.report.volume_fraction, 0.8, 1e-9);
  EXPECT_GE(p.walls.gap(), kMinWallGap);
  // The walls as a run sets them again on the relaxed packing.
  ContactSystem again(p.packing.particles, p.packing.box, named_law("piecewise"), spec.skin);
  EXPECT_NO_THROW(again.set_walls(p.walls));
  for (const Vec3& x : p.packing.particles.position) {
    EXPECT_GT(x.y(), p.walls.lower);
    EXPECT_LT(x.y(), p.walls.upper);
  }
}

// The local mean flow (model/solvent_flow.h): cloud-in-cell means on nodes
// one radius apart, linear between them. Exact identities: the friction
// against it exerts no net force whatever the particles do, a plug is
// reproduced wherever its particles sit, so is a linear profile sampled
// symmetrically about the interior nodes, and a node that loses its particles
// keeps its last mean.
TEST(SolventFlow, IsTheFrictionWeightedLocalMeanAndExertsNoNetForce) {
  EXPECT_EQ(SolventFlow().velocity(3.0, 1.0), 0.0);  // affine: no non-affine solvent flow
  EXPECT_THROW(SolventFlow::local_mean(5.0, 5.0), InputError);
  SolventFlow flow = SolventFlow::local_mean(2.0, 12.0);  // nodes at 2.5, 3.5, ..., 11.5
  ASSERT_EQ(flow.profile().size(), 10u);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> height(1.8, 12.2), speed(-3.0, 3.0), zeta(0.5, 2.0);
  std::vector<Vec3> x, v;
  std::vector<double> friction;
  for (int a = 0; a < 300; ++a) {
    x.emplace_back(0.0, height(rng), 0.0);
    v.emplace_back(speed(rng), speed(rng), 0.0);
    friction.push_back(zeta(rng));
  }
  flow.update(x, v, friction, 0.4);
  double momentum = 0.0, reference = 0.0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    momentum += friction[a] * v[a].x();
    reference += friction[a] * flow.velocity(x[a].y(), 0.4);
  }
  EXPECT_NEAR(reference, momentum, 1e-12 * x.size());
  // A plug, u_x = c y + v_x = U for every particle, is its own mean flow
  // wherever the particles sit: v̄(y_α) = v_α,x.
  for (std::size_t a = 0; a < x.size(); ++a) v[a].x() = 1.3 - 0.4 * x[a].y();
  flow.update(x, v, friction, 0.4);
  for (std::size_t a = 0; a < x.size(); ++a)
    EXPECT_NEAR(flow.velocity(x[a].y(), 0.4), v[a].x(), 1e-13);

  x.clear(), v.clear(), friction.clear();
  for (int k = 0; k < 10; ++k)
    for (const double y : {2.25 + k, 2.75 + k}) {
      x.emplace_back(0.0, y, 0.0);
      v.emplace_back(0.5 * y - 1.0, 7.0, -3.0);  // only v_x counts
      friction.push_back(1.5);
    }
  flow.update(x, v, friction, 0.4);
  for (const double y : {3.5, 4.1, 7.77, 10.5})
    EXPECT_NEAR(flow.velocity(y, 0.4), 0.5 * y - 1.0, 1e-14) << y;
  // ū is constant beyond the outer nodes.
  EXPECT_NEAR(flow.velocity(1.0, 0.4) + 0.4 * 1.0, flow.velocity(2.5, 0.4) + 0.4 * 2.5, 1e-14);
  flow.update(std::span(x).first(2), std::span(v).first(2), std::span(friction).first(2), 0.4);
  EXPECT_NEAR(flow.velocity(7.77, 0.4), 0.5 * 7.77 - 1.0, 1e-14);
}

// N = 150 at φ = 0.80 between walls (a gap of 7 R), the piecewise law.
struct SmallWallPacking {
  PackingSpec spec = testing::small_packing_spec(1, 0.8, 150);
  std::shared_ptr<const ContactLaw> law = named_law("piecewise");
  WallPacking packing = make_wall_packing(spec, law);

  OverdampedShear flow(const ShearModel& model) const {
    ContactSystem system(packing.packing.particles, packing.packing.box, law, spec.skin);
    system.set_walls(packing.walls);
    return OverdampedShear(std::move(system), model);
  }
};

// Below the yield stress the particles between smooth walls move as a plug
// that slips on both walls. Against the affine flow the reservoir friction
// pulls every particle of the plug towards the affine velocity at its height,
// a body force that the bulk stress must carry on top of the wall stress
// (here it outweighs σ_w and shears the slab); against the local mean flow
// the plug has nothing to push against but the walls, and the bulk carries
// the wall stress (to the fluctuations about the slab means: 2 % of it).
TEST(WallRun, APlugCarriesTheWallStressOnlyAgainstTheLocalMeanFlow) {
  const SmallWallPacking small;
  const WallPacking& p = small.packing;
  auto summary = [&](bool local_mean) {
    ShearModel model;
    model.gamma_tilde = 1e-5;  // σ_w ≈ 3e-4 E*, a quarter of σ_y
    OverdampedShear flow = small.flow(model);
    if (local_mean) flow.set_solvent_flow(SolventFlow::local_mean(p.walls.lower, p.walls.upper));
    const auto integrator = make_integrator({.name = "euler", .tolerance = 1e-4});
    WallRunSpec run_spec;
    run_spec.strain = 1.0;
    run_spec.sample_interval = 0.01;
    return summarise_wall_run(run_wall_shear(flow, *integrator, run_spec));
  };
  auto mean = [](const WallRunSummary& s, const char* name) {
    return find_estimate(s.estimates, name).mean;
  };
  for (const bool local_mean : {false, true}) {
    const WallRunSummary s = summary(local_mean);
    const double wall = mean(s, "wall_stress_lower"), bulk = mean(s, "bulk_stress");
    if (local_mean) {
      // A plug (the bulk shears at under 1 % of the apparent rate) carrying σ_w.
      EXPECT_LT(std::abs(mean(s, "bulk_rate")), 0.01);
      EXPECT_GT(wall, 0.0);
      EXPECT_NEAR(bulk, wall, 0.02 * wall);
    } else {
      // The body force shears the slab and outweighs the walls' stress.
      EXPECT_GT(std::abs(bulk - wall), std::abs(wall));
    }
  }
}

// Force balance: at every sample the central bulk stress less the reservoir
// friction's share equals the lower wall's stress, and the upper wall's less
// the whole reservoir friction the lower's, to the velocity solve's tolerance.
TEST(WallRun, WallStressBalancesTheBulkStress) {
  const SmallWallPacking small;
  const WallPacking& p = small.packing;
  const PackingSpec& spec = small.spec;
  ShearModel model;
  model.gamma_tilde = 1e-4;
  OverdampedShear flow = small.flow(model);
  const auto integrator = make_integrator({.name = "euler", .tolerance = 1e-4});
  WallRunSpec run_spec;
  run_spec.strain = 3.0;
  run_spec.sample_interval = 0.02;
  const WallRunResult run = run_wall_shear(flow, *integrator, run_spec);
  ASSERT_EQ(run.samples.size(), 150u);

  // The solve leaves each particle a force residual ≤ tol ζ max(1, max|v|);
  // summed over N particles per wall area that bounds the balance's error.
  // Between walls moving at ±cH/2 about the centre no particle's non-affine
  // speed reaches cH (a plug's is at most cH/2 and the fluctuations are far
  // smaller), so max(1, H) bounds max(1, max|v|).
  const double area = p.packing.box.side() * p.packing.box.side();
  const double zeta = model.friction(p.packing.particles.max_radius());
  const double bound = static_cast<double>(spec.particles) * model.drag.tolerance * zeta *
                       std::max(1.0, p.walls.gap()) / area;
  for (const WallSample& s : run.samples) {
    EXPECT_NEAR(s.bulk_stress - s.reservoir_term, s.wall_stress_lower, bound);
    EXPECT_NEAR(s.wall_stress_upper - s.reservoir_total, s.wall_stress_lower, bound);
  }

  // Over the steady part: the walls are dragged forward, the bulk flows slower
  // than the walls impose (slip), and the balance holds for the means within
  // their standard errors.
  const WallRunSummary summary = summarise_wall_run(run);
  const MeanEstimate& lower = find_estimate(summary.estimates, "wall_stress_lower");
  const MeanEstimate& balance = find_estimate(summary.estimates, "balance");
  EXPECT_GT(lower.mean, 0.0);
  EXPECT_GT(find_estimate(summary.estimates, "slip_velocity").mean, 0.0);
  EXPECT_NEAR(lower.mean, balance.mean,
              bound + 3.0 * std::hypot(lower.standard_error, balance.standard_error));
}

}  // namespace
}  // namespace softglass::micro
