// The narrow contact list of ContactSystem (contact_system.h) changes the cost
// of an evaluation, never its result: at every configuration of a sheared run,
// with the explicit and the implicit scheme (whose wide list margins the
// narrow list cannot always hold), the forces, stiffness sums, virial and
// contacts are the same bits as a loop over the wide list gives.
#include <gtest/gtest.h>

#include <cstdio>

#include "micro/dynamics/integrator.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

struct ListUse {
  int evaluations = 0, narrow = 0;
  std::size_t filterings = 0;  // of the narrow list
};

// Shears a small packing over `strain`, comparing after every step.
ListUse compare_along_a_run(const IntegratorSpec& spec, double gamma_tilde, double strain) {
  PackingSpec packing_spec;
  packing_spec.particles = 256;
  packing_spec.volume_fraction = 0.8;
  packing_spec.seed = 4;
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(packing_spec, law);
  ShearModel model;
  model.gamma_tilde = gamma_tilde;
  OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, 0.6), model);
  const auto integrator = make_integrator(spec);
  ListUse use;
  const ForceRequest request{.energy = true, .contacts = true, .virial = true};
  while (flow.strain() < strain) {
    integrator->step(flow, strain - flow.strain());
    ContactSystem& system = flow.system();
    if (&system.contact_list() != &system.neighbours()) {
      ++use.narrow;
      use.filterings = system.contact_list().builds();
    }
    ++use.evaluations;
    const ContactField& got = system.compute_forces(request);
    ContactField wide;
    compute_contact_forces(system.law(), system.box(), system.particles().position,
                           system.neighbours(), request, wide);
    EXPECT_EQ(got.contact_count, wide.contact_count);
    EXPECT_EQ(got.energy, wide.energy);
    EXPECT_EQ(got.virial, wide.virial);
    EXPECT_EQ(got.force, wide.force);
    EXPECT_EQ(got.stiffness_sum, wide.stiffness_sum);
    EXPECT_EQ(got.contacts.j, wide.contacts.j);
    if (::testing::Test::HasFailure()) break;
  }
  return use;
}

TEST(ContactSystem, NarrowListGivesTheWideListsBitsWithTheExplicitScheme) {
  const ListUse use = compare_along_a_run({.name = "euler"}, 1e-5, 0.1);
  // The narrow list served (nearly) every evaluation.
  EXPECT_GT(use.narrow, use.evaluations * 9 / 10) << use.narrow << " of " << use.evaluations;
  EXPECT_GT(use.filterings, 3u);
  std::printf("[ measured ] explicit: the narrow list served %d of %d steps, %zu filterings\n",
              use.narrow, use.evaluations, use.filterings);
}

TEST(ContactSystem, NarrowListGivesTheWideListsBitsWithTheImplicitScheme) {
  const ListUse use = compare_along_a_run({.name = "bdf2"}, 1e-8, 0.1);
  EXPECT_GT(use.evaluations, 20);
  EXPECT_GT(use.narrow, 0) << "the narrow list never served: the test says little";
  EXPECT_GT(use.filterings, 3u);
  std::printf("[ measured ] implicit: the narrow list served %d of %d steps, %zu filterings\n",
              use.narrow, use.evaluations, use.filterings);
}

}  // namespace
}  // namespace softglass::micro
