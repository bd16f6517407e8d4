// Particles that never touch follow the imposed flow exactly and carry no stress.
//
// Construction: 200 spheres (radii 1 ± 10 %) in 8 layers of constant y, layers
// L/8 ≈ 2.5 apart (> 2 R_max = 2.2, also across the periodic boundary), and
// non-overlapping within a layer. Simple shear moves particles only along x with
// a speed that depends on y alone, so particles of one layer never move relative
// to each other and particles of different layers are always further apart than
// R_i + R_j in y: no contact at any strain, whatever the Lees–Edwards offset.
// φ ≈ 0.1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "micro/contact/contact_law.h"
#include "micro/dynamics/integrator.h"
#include "micro/model/overdamped_shear.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

struct Layered {
  std::vector<Vec3> x;
  std::vector<double> r;
  double side;
};

Layered layered_configuration() {
  constexpr int layers = 8, per_layer = 25;
  Layered c;
  c.side = 20.5;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> radius(0.9, 1.1), coordinate(0.0, c.side);
  for (int layer = 0; layer < layers; ++layer) {
    const double y = (layer + 0.5) * c.side / layers;
    for (int placed = 0; placed < per_layer;) {
      const double r = radius(rng);
      const Vec3 x(coordinate(rng), y, coordinate(rng));
      bool free = true;
      for (std::size_t k = 0; k < c.x.size(); ++k) {
        if (c.x[k].y() != y) continue;
        const Vec3 d = testing::brute_force_separation(x, c.x[k], c.side, 0.0);
        free = free && d.norm() > r + c.r[k] + 0.05;
      }
      if (!free) continue;
      c.x.push_back(x);
      c.r.push_back(r);
      ++placed;
    }
  }
  return c;
}

TEST(AffineFlow, NonTouchingParticlesFollowTheFlowWithZeroStress) {
  const Layered c = layered_configuration();
  ASSERT_GT(c.side / 8, 2.2);  // layers can never touch
  ShearModel model;
  model.gamma_tilde = 1e-4;  // any rate: without contacts there is no force at all
  OverdampedShear flow(ContactSystem(Particles(c.x, c.r), LeesEdwardsBox(c.side),
                                     testing::named_law("seth2011"), 0.3),
                       model);
  EXPECT_LT(flow.system().volume_fraction(), 0.11);
  const auto integrator = make_integrator({.name = "euler"});

  // 2.7 strain units: the top layer moves by 2.7 × 19.2 ≈ 52 ≈ 2.5 L, so x
  // wraps several times and the Lees–Edwards offset sweeps through [0, L).
  constexpr double target = 2.7;
  std::size_t steps = 0;
  while (flow.strain() < target - 1e-12) {
    integrator->step(flow, target - flow.strain());
    ++steps;
    // Every evaluation along the way: no contact, no velocity, no stress.
    ASSERT_EQ(flow.contact_count(), 0u) << "strain " << flow.strain();
    for (const Vec3& v : flow.velocities()) ASSERT_TRUE((v.array() == 0.0).all()) << v.transpose();
    const StressSample s = flow.stress();
    ASSERT_TRUE((s.elastic.array() == 0.0).all() && (s.viscous.array() == 0.0).all());
  }
  EXPECT_NEAR(flow.strain(), target, 1e-12);
  EXPECT_GT(steps, 10u);  // max step 0.05 strain: the affine update was applied many times

  // Positions: x0 + γ y0 e_x modulo L in x, y and z untouched (bit for bit,
  // since the displacement has no y or z part). x accumulates one rounding of
  // ≲ L·2⁻⁵³ per step, so 1e-11 ≫ 60 steps × 2e-15.
  const Particles& p = flow.system().particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x0 = c.x[p.label[i]];
    EXPECT_EQ(p.position[i].y(), x0.y());
    EXPECT_EQ(p.position[i].z(), x0.z());
    const double expected = std::fmod(x0.x() + flow.strain() * x0.y(), c.side);
    double error = std::abs(p.position[i].x() - expected);
    error = std::min(error, c.side - error);  // compare on the circle
    EXPECT_LT(error, 1e-11) << "particle " << p.label[i];
  }
}

}  // namespace
}  // namespace softglass::micro
