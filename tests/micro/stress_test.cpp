// The virial stress σ^e_ij = −(1/V) Σ_pairs d_i f_j (docs/physics.md, "Stress"), computed by hand
// for two- and three-particle configurations with the Hertz law written out in
// its dimensional form f = (4/3) E* R_c^{1/2} h^{3/2}, and compared with the
// engine — including a pair that touches only across the Lees–Edwards boundary.
//
// Reduced units: E* = 1, lengths in R. Cell side L = 20 (V = 8000) and skin 0.1,
// so the neighbour grid is fine with a handful of particles.
#include <gtest/gtest.h>

#include <cmath>

#include "micro/contact/contact_law.h"
#include "micro/model/overdamped_shear.h"
#include "micro/model/contact_system.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

constexpr double kSide = 20.0;
constexpr double kVolume = kSide * kSide * kSide;

// Hertz force on a from b, for the separation d = x_a − x_b (by construction).
Vec3 hertz_force(double ra, double rb, const Vec3& d) {
  const double h = ra + rb - d.norm();
  if (h <= 0.0) return Vec3::Zero();
  const double rc = ra * rb / (ra + rb);
  return (4.0 / 3.0) * std::sqrt(rc) * std::pow(h, 1.5) * d.normalized();
}

ContactSystem make_system(std::vector<Vec3> x, std::vector<double> r, double strain) {
  LeesEdwardsBox box(kSide);
  box.set_strain(strain);
  return ContactSystem(Particles(std::move(x), std::move(r)), box, testing::named_law("hertz"),
                       0.1);
}

Eigen::Matrix3d elastic_stress(ContactSystem& system) {
  return -system.compute_forces().virial / system.box().volume();
}

// All comparisons are of closed-form expressions evaluated in a different
// order: relative 1e-13 of the stress scale is ~500 ulp.
void expect_tensor_near(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected) {
  const double scale = expected.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), 1e-13 * scale) << "actual\n"
                                                                      << actual << "\nexpected\n"
                                                                      << expected;
}

TEST(VirialStress, CompressionalPairHasPositiveShearStress) {
  // Two unit spheres overlapping by h = 0.1 along the compressional axis
  // (1, −1, 0)/√2 of u = γ̇ y e_x: d = x_α − x_β = r (1, −1, 0)/√2, f = |f| d/r.
  //     σ = −(1/V) d ⊗ f:  σ_yx = σ_xy = +|f| r/(2V),  σ_xx = σ_yy = −|f| r/(2V),
  // σ_zz = 0; hence N1 = 0, N2 = −|f| r/(2V), Π = |f| r/(3V) (docs/physics.md, "Stress": signs).
  const double r = 1.9;
  const Vec3 alpha(10.0, 10.0, 10.0);
  const Vec3 d = r * Vec3(1.0, -1.0, 0.0).normalized();
  ContactSystem system = make_system({alpha, alpha - d}, {1.0, 1.0}, 0.0);

  const double f = (4.0 / 3.0) * std::sqrt(0.5) * std::pow(0.1, 1.5);  // R_c = 1/2, h = 0.1
  const double s = f * r / (2.0 * kVolume);
  Eigen::Matrix3d expected;
  expected << -s, s, 0, s, -s, 0, 0, 0, 0;
  const Eigen::Matrix3d sigma = elastic_stress(system);
  expect_tensor_near(sigma, expected);

  const ShearObservables o = observables(sigma);
  EXPECT_GT(o.shear, 0.0);
  EXPECT_NEAR(o.shear, s, 1e-13 * s);
  EXPECT_NEAR(o.n1, 0.0, 1e-13 * s);
  EXPECT_NEAR(o.n2, -s, 1e-13 * s);
  EXPECT_NEAR(o.pressure, 2.0 * s / 3.0, 1e-13 * s);
}

TEST(VirialStress, ExtensionalPairHasNegativeShearStress) {
  // The mirror image along (1, 1, 0): σ_yx = −|f| r/(2V).
  const double r = 1.9;
  const Vec3 alpha(10.0, 10.0, 10.0);
  ContactSystem system =
      make_system({alpha, alpha - r * Vec3(1.0, 1.0, 0.0).normalized()}, {1.0, 1.0}, 0.0);
  const double f = (4.0 / 3.0) * std::sqrt(0.5) * std::pow(0.1, 1.5);
  EXPECT_NEAR(observables(elastic_stress(system)).shear, -f * r / (2.0 * kVolume),
              1e-13 * f * r / kVolume);
}

// Three particles of different radii, particle 0 near the top of the cell:
//   0–1 overlap inside the cell, d01 = (−1.3, 1.1, 0.6);
//   0–2 overlap only across the gradient boundary: 2 sits near the bottom, and at
//   strain 0.5 its image above, shifted by δ = 0.5 L = 10 in x, is at x_0 − d02
//   with d02 = (0.9, −1.6, 0.4).
// Both pairs lie in the compressional quadrant (d_x d_y < 0): σ_yx > 0.
struct ThreeParticles {
  std::vector<Vec3> x;
  std::vector<double> r = {1.2, 0.9, 1.0};
  Vec3 d01{-1.3, 1.1, 0.6};
  Vec3 d02{0.9, -1.6, 0.4};
  ThreeParticles() {
    const Vec3 x0(6.0, 18.8, 7.0);
    const Vec3 image_of_2 = x0 - d02;  // (5.1, 20.4, 6.6): above the cell
    const Vec3 x2(image_of_2.x() - 0.5 * kSide + kSide, image_of_2.y() - kSide, image_of_2.z());
    x = {x0, x0 - d01, x2};
  }
  Vec3 f01() const { return hertz_force(r[0], r[1], d01); }
  Vec3 f02() const { return hertz_force(r[0], r[2], d02); }
};

TEST(VirialStress, ThreeParticlesAcrossTheLeesEdwardsBoundary) {
  const ThreeParticles t;
  ASSERT_GT(t.f01().norm(), 0.0);
  ASSERT_GT(t.f02().norm(), 0.0);
  const Eigen::Matrix3d expected =
      -(t.d01 * t.f01().transpose() + t.d02 * t.f02().transpose()) / kVolume;

  // Strain 0.5, and 3.5 (same offset after three more box lengths).
  for (double strain : {0.5, 3.5}) {
    ContactSystem system = make_system(t.x, t.r, strain);
    const Eigen::Matrix3d sigma = elastic_stress(system);
    expect_tensor_near(sigma, expected);
    EXPECT_EQ(system.forces().contact_count, 2u) << "strain " << strain;

    // Forces by hand: F0 = f01 + f02, F1 = −f01, F2 = −f02 (particles are
    // reordered inside the system; `label` is the original index).
    const Particles& p = system.particles();
    const std::vector<Vec3> by_hand = {t.f01() + t.f02(), -t.f01(), -t.f02()};
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_LE((system.forces().force[i] - by_hand[p.label[i]]).norm(), 1e-13 * t.f02().norm())
          << "particle " << p.label[i] << " at strain " << strain;
    }

    // The reported observables, from the hand-computed tensor.
    const ShearObservables o = observables(sigma);
    const double scale = expected.cwiseAbs().maxCoeff();
    EXPECT_NEAR(o.shear, expected(1, 0), 1e-13 * scale);
    EXPECT_GT(o.shear, 0.0);
    EXPECT_NEAR(o.n1, expected(0, 0) - expected(1, 1), 1e-13 * scale);
    EXPECT_NEAR(o.n2, expected(1, 1) - expected(2, 2), 1e-13 * scale);
    EXPECT_NEAR(o.pressure, -expected.trace() / 3.0, 1e-13 * scale);
  }

  // At strain 0 the image of 2 sits 10 further along x: only 0–1 remains.
  ContactSystem unsheared = make_system(t.x, t.r, 0.0);
  expect_tensor_near(elastic_stress(unsheared), -(t.d01 * t.f01().transpose()) / kVolume);
  EXPECT_EQ(unsheared.forces().contact_count, 1u);
}

TEST(VirialStress, DynamicsReportsTheSameElasticStress) {
  // OverdampedShear::stress() must use the same convention σ = −virial/V; with
  // the EHD drag off its viscous part is exactly zero.
  const ThreeParticles t;
  ShearModel model;
  model.gamma_tilde = 1e-4;
  model.drag.enabled = false;
  OverdampedShear flow(make_system(t.x, t.r, 0.5), model);
  flow.evaluate();
  const StressSample s = flow.stress();
  expect_tensor_near(s.elastic,
                     -(t.d01 * t.f01().transpose() + t.d02 * t.f02().transpose()) / kVolume);
  EXPECT_TRUE((s.viscous.array() == 0.0).all()) << s.viscous;
}

TEST(ShearObservables, DefinitionsOnAGeneralTensor) {
  // σ = σ_yx (not σ_xy: the viscous tensor is not symmetric), N1 = σxx − σyy,
  // N2 = σyy − σzz, Π = −tr σ/3. Exact in binary for these entries.
  Eigen::Matrix3d s;
  s << 1.0, 2.0, 3.0,  //
      5.0, 7.0, 11.0,  //
      13.0, 17.0, 19.0;
  const ShearObservables o = observables(s);
  EXPECT_EQ(o.shear, 5.0);
  EXPECT_EQ(o.n1, -6.0);
  EXPECT_EQ(o.n2, -12.0);
  EXPECT_EQ(o.pressure, -9.0);
}

}  // namespace
}  // namespace softglass::micro
