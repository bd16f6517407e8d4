// Elastic pair forces are equal and opposite (Newton's third law), so the total
// elastic force on a periodic configuration vanishes; and each contact in the
// ContactList carries the force of the contact law at its own geometry.
#include <gtest/gtest.h>

#include <omp.h>

#include <cfloat>

#include "micro/contact/contact_law.h"
#include "micro/model/contact_system.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

using testing::random_configuration;

class PairForces : public ::testing::TestWithParam<double> {};

// 200 particles placed at random at φ = 0.6: heavily overlapping (ε up to ~1,
// all three seth2011 branches), with contacts across the Lees–Edwards boundary.
ContactSystem overlapping_system(double strain) {
  const auto c = random_configuration(200, 0.6, 99);
  LeesEdwardsBox box(c.side);
  box.set_strain(strain);
  return ContactSystem(Particles(c.position, c.radius), box, testing::named_law("seth2011"), 0.3);
}

TEST_P(PairForces, TotalForceVanishes) {
  ContactSystem system = overlapping_system(GetParam());
  const ContactField& field = system.compute_forces();
  ASSERT_GT(field.contact_count, 300u);
  Vec3 total = Vec3::Zero();
  for (const Vec3& f : field.force) total += f;
  // Every pair force is added to one particle and subtracted from another, so
  // Σ F_i = 0 up to the rounding of the sums: ≲ (terms per sum + N) 2⁻⁵³ Σ|f_c|
  // ≈ 220 × 1.1e-16 ≈ 2.5e-14 of Σ|f_c|; 1e-13 allows for that.
  EXPECT_LE(total.norm(), 1e-13 * field.force_magnitude_sum) << "total " << total.transpose();
  // and the test is not trivially satisfied: individual forces are O(Σ|f|/N)
  double largest = 0.0;
  for (const Vec3& f : field.force) largest = std::max(largest, f.norm());
  EXPECT_GT(largest, 1e-3 * field.force_magnitude_sum);
}

TEST_P(PairForces, ThirdLawPerPairThroughTheContactList) {
  ContactSystem system = overlapping_system(GetParam());
  const double strain = GetParam();
  const ContactField& field = system.compute_forces({.contacts = true});
  const ContactList& c = field.contacts;
  const Particles& p = system.particles();
  const std::size_t n = system.size();
  ASSERT_EQ(c.size(), field.contact_count);
  const auto seth = testing::named_law("seth2011");

  // Each contact: geometry from an independent nearest-image search, force
  // from the law at that geometry, up to a handful of roundings.
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::uint32_t i = c.i[k], j = c.j[k];
    const Vec3 d =
        testing::brute_force_separation(p.position[i], p.position[j], system.box().side(), strain);
    EXPECT_LT((c.separation[k] - d).norm(), 1e-12 * system.box().side()) << "contact " << k;
    const double r = d.norm();
    const double rc = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
    const double eps = (p.radius[i] + p.radius[j] - r) / rc;
    EXPECT_NEAR(c.contact_radius[k] / rc, 1.0, 1e-14);
    EXPECT_NEAR(c.deformation[k], eps, 1e-12 * std::max(1.0, eps));
    // ε itself carries an absolute rounding of ~1e-15 (r and R_i + R_j are O(1)),
    // which moves f by R_c² F'(ε) δε: large relative to f for tiny overlaps.
    EXPECT_NEAR(c.force[k], rc * rc * seth->force(eps),
                1e-13 * rc * rc * seth->force(eps) + rc * rc * seth->stiffness(eps) * 1e-14);
  }

  // Rebuild every particle's force as Σ over its contacts of +f_c n_c (as i)
  // and −f_c n_c (as j): this holds only if each contact acts on its two
  // particles with equal and opposite forces.
  std::vector<Vec3> rebuilt(n, Vec3::Zero());
  std::vector<double> scale(n, 0.0);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3 f = c.force[k] * c.separation[k].normalized();  // on i from j, repulsive
    rebuilt[c.i[k]] += f;
    rebuilt[c.j[k]] -= f;
    scale[c.i[k]] += c.force[k];
    scale[c.j[k]] += c.force[k];
  }
  for (std::size_t a = 0; a < n; ++a) {
    // summation order differs from the engine's: a few ulp of Σ|f| per particle
    EXPECT_LE((field.force[a] - rebuilt[a]).norm(), 1e-13 * scale[a] + 1e-300) << "particle " << a;
  }
  // Repulsion: the force on i from j points from j to i (f·d > 0).
  for (std::size_t k = 0; k < c.size(); ++k) EXPECT_GT(c.force[k], 0.0);
}

// The list's 1/r is the reciprocal of |d| to a rounding or two (the kernel
// takes it as 1/√(d·d)), and the virial summed over the list is the kernel's
// Σ d ⊗ f up to the order and fusing of the sums: a few ulp of Σ|f_c| r.
TEST_P(PairForces, ContactListCarriesTheKernelsDistanceAndVirial) {
  ContactSystem system = overlapping_system(GetParam());
  const ContactField& field = system.compute_forces({.contacts = true, .virial = true});
  const ContactList& c = field.contacts;
  ASSERT_GT(c.size(), 300u);
  double scale = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double r = c.separation[k].norm();
    EXPECT_NEAR(c.inverse_distance[k] * r, 1.0, 4 * DBL_EPSILON) << "contact " << k;
    scale += c.force[k] * r;
  }
  const Eigen::Matrix3d summed = c.virial();
  EXPECT_LE((summed - field.virial).norm(), 1e-13 * scale);
  EXPECT_LE((summed - summed.transpose()).norm(), 0.0);  // symmetric by construction
  EXPECT_GT(field.virial.norm(), 1e-3 * scale);          // and not trivially small
}

// current_forces hands back the last evaluation while the configuration is
// the one it was made at and it computed what is asked for; any move, shear,
// strain, restore or rebuild makes it evaluate again.
TEST(CurrentForces, ReusedOnlyAtTheConfigurationTheyWereComputedAt) {
  ContactSystem system = overlapping_system(0.1);
  const std::size_t n = system.size();
  const double energy = system.compute_forces({.energy = true, .contacts = true}).energy;
  ASSERT_GT(energy, 0.0);
  const std::vector<Vec3> at_start = system.forces().force;
  const auto same_as_fresh = [&](const ForceRequest& request) {
    const ContactField& reused = system.current_forces(request);
    const std::vector<Vec3> forces = reused.force;
    const std::size_t contacts = reused.contacts.size();
    const ContactField& fresh = system.compute_forces(request);
    return forces == fresh.force && contacts == fresh.contacts.size();
  };

  // Reused: the very object, with the energy and contacts it had.
  const ContactField& again = system.current_forces({.contacts = true, .virial = false});
  EXPECT_EQ(&again, &system.forces());
  EXPECT_EQ(again.energy, energy);
  EXPECT_EQ(again.force, at_start);
  // A request for more than was computed (the virial) evaluates again.
  system.compute_forces({.energy = true, .contacts = true, .virial = false});
  EXPECT_EQ(system.current_forces({.virial = true}).virial,
            system.compute_forces({.virial = true}).virial);

  // Each change of the configuration is seen.
  std::vector<Vec3> push(n, Vec3(1e-3, -2e-3, 5e-4));
  system.compute_forces({.contacts = true});
  system.move(1.0, push);
  EXPECT_NE(system.current_forces({.contacts = true}).force, at_start);
  EXPECT_TRUE(same_as_fresh({.contacts = true}));
  system.shear(1e-3);
  EXPECT_TRUE(same_as_fresh({.contacts = true}));
  const std::vector<Vec3> positions = system.particles().position;
  const double strain = system.box().strain();
  system.move(1.0, push);
  system.compute_forces({.contacts = true});
  system.restore_positions(positions, strain);
  EXPECT_TRUE(same_as_fresh({.contacts = true}));
  system.compute_forces({.contacts = true});
  system.set_strain(strain + 0.01);  // rebuilds, reordering the particles
  EXPECT_TRUE(same_as_fresh({.contacts = true}));
}

INSTANTIATE_TEST_SUITE_P(Strains, PairForces, ::testing::Values(0.0, 0.37));

// From 2048 particles the kernel splits its blocks over the threads, which add
// the shares of the particles outside their own range into private arrays,
// reduced afterwards; with one thread it runs without a parallel region. Both
// paths give the same forces, contact list and totals up to the order of the
// sums: per particle a few ulp of its Σ|f| (as above), the totals a few ulp of
// Σ|f_c| r (virial) or Σ E_c.
TEST(PairForcesThreads, TwoThreadsGiveTheOneThreadFieldUpToTheOrderOfSums) {
  const auto c = random_configuration(3000, 0.6, 7);
  const ForceRequest request{.energy = true, .contacts = true, .virial = true};
  const int threads_before = omp_get_max_threads();
  const auto field_with = [&](int threads) {
    omp_set_num_threads(threads);
    ContactSystem system(Particles(c.position, c.radius), LeesEdwardsBox(c.side),
                         testing::named_law("seth2011"), 0.3);
    ContactField field = system.compute_forces(request);
    omp_set_num_threads(threads_before);
    return field;
  };
  const ContactField one = field_with(1), two = field_with(2);
  ASSERT_GT(one.contact_count, 3000u);
  EXPECT_EQ(one.contact_count, two.contact_count);
  EXPECT_EQ(one.contacts.size(), two.contacts.size());
  std::vector<double> scale(one.force.size(), 0.0);
  for (std::size_t k = 0; k < one.contacts.size(); ++k) {
    scale[one.contacts.i[k]] += one.contacts.force[k];
    scale[one.contacts.j[k]] += one.contacts.force[k];
  }
  for (std::size_t a = 0; a < one.force.size(); ++a)
    EXPECT_LE((one.force[a] - two.force[a]).norm(), 1e-13 * scale[a] + 1e-300) << "particle " << a;
  EXPECT_NEAR(one.energy, two.energy, 1e-12 * one.energy);
  EXPECT_NEAR(one.force_magnitude_sum, two.force_magnitude_sum, 1e-12 * one.force_magnitude_sum);
  EXPECT_LE((one.virial - two.virial).norm(), 1e-12 * one.virial.norm());
}

}  // namespace
}  // namespace softglass::micro
