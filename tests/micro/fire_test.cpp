// FIRE relaxation (packing/fire.h): it lowers the elastic energy and reaches
// force balance, judged by forces recomputed after it returns.
#include <gtest/gtest.h>

#include "common/errors.h"
#include "micro/contact/contact_law.h"
#include "micro/packing/fire.h"
#include "micro/model/contact_system.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

ContactSystem random_system(std::size_t n, double phi, std::uint64_t seed,
                            const char* law = "seth2011") {
  const auto c = testing::random_configuration(n, phi, seed);
  return ContactSystem(Particles(c.position, c.radius), LeesEdwardsBox(c.side),
                       testing::named_law(law), 0.3);
}

// Σ_c R_c³ W(ε_c), recomputed from the contact list.
double energy_from_contacts(ContactSystem& system) {
  const ContactList& c = system.compute_forces({.contacts = true}).contacts;
  double e = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k)
    e += std::pow(c.contact_radius[k], 3) * system.law().energy(c.deformation[k]);
  return e;
}

TEST(Fire, RelaxesAJammedConfigurationToForceBalance) {
  // 250 particles at random at φ = 0.8: far above jamming, so the relaxed state
  // keeps a force network (it cannot relax to zero energy).
  ContactSystem system = random_system(250, 0.8, 31);
  const double before = system.compute_forces({.energy = true}).energy;
  ASSERT_NEAR(energy_from_contacts(system), before, 1e-12 * before);

  const FireSettings settings{.force_tolerance = 1e-10};
  const FireResult result = minimise_fire(system, settings);
  std::printf("[ measured ] FIRE: %zu iterations, energy %.6e -> %.6e, residual %.2e\n",
              result.iterations, before, result.energy, result.residual);
  ASSERT_TRUE(result.converged);
  EXPECT_FALSE(result.unjammed);
  EXPECT_LE(result.residual, settings.force_tolerance);
  EXPECT_LT(result.energy, before);
  EXPECT_GT(result.energy, 0.0);

  // Recompute everything independently of the minimiser's bookkeeping: the
  // energy it reports is the configuration's, and the largest net force is
  // below tolerance × mean contact force (same configuration, same sums).
  EXPECT_NEAR(energy_from_contacts(system), result.energy, 1e-12 * result.energy);
  const ContactField& field = system.compute_forces();
  double largest = 0.0;
  for (const Vec3& f : field.force) largest = std::max(largest, f.norm());
  const double mean_contact_force = field.force_magnitude_sum / double(field.contact_count);
  EXPECT_LE(largest, settings.force_tolerance * mean_contact_force);
  EXPECT_DOUBLE_EQ(force_residual(field), largest / mean_contact_force);
  // "small" in absolute terms as well: contact forces are ≳ 1e-3 E* R² here.
  EXPECT_GT(mean_contact_force, 1e-3);
  // Velocities are left at zero (the packing is at rest).
  for (const Vec3& v : system.particles().velocity) EXPECT_EQ(v, Vec3::Zero());
}

TEST(Fire, EnergyDecreasesMonotonicallyOverSuccessiveBudgets) {
  // Stopping FIRE after 50, 100, 200, ... iterations (restarting from where it
  // stopped): every budget must leave the energy lower, never higher.
  ContactSystem system = random_system(200, 0.75, 7);
  double energy = system.compute_forces({.energy = true}).energy;
  for (std::size_t budget : {50u, 100u, 200u, 400u}) {
    const FireResult r =
        minimise_fire(system, {.force_tolerance = 1e-12, .max_iterations = budget});
    EXPECT_FALSE(r.converged) << "budget " << budget << " was enough; the test needs smaller ones";
    EXPECT_LT(r.energy, energy) << "after " << budget << " more iterations";
    energy = r.energy;
  }
}

TEST(Fire, DiluteConfigurationRelaxesToZeroEnergy) {
  // At φ = 0.3 every overlap can be removed: FIRE ends "unjammed" with the
  // contacts carrying (almost) nothing. The criterion is a mean contact force
  // below 1e-12, i.e. an energy per contact ≲ (1e-12)^{5/3} — effectively zero.
  ContactSystem system = random_system(200, 0.3, 5, "hertz");
  const double before = system.compute_forces({.energy = true}).energy;
  ASSERT_GT(before, 1.0);
  const FireResult r = minimise_fire(system, {});
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.energy, 1e-15 * before);
}

TEST(Fire, InvalidSettingsAreRejected) {
  ContactSystem system = random_system(200, 0.5, 1);
  EXPECT_THROW(minimise_fire(system, {.force_tolerance = 0.0}), InputError);
  EXPECT_THROW(minimise_fire(system, {.force_tolerance = 1e-9, .max_iterations = 0}), InputError);
  EXPECT_THROW(minimise_fire(system, {.step_fraction = 2.5}), InputError);
}

}  // namespace
}  // namespace softglass::micro
