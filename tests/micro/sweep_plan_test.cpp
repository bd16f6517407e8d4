// The sweep plan: presets as documented, lists checked, packings shared across
// rates, every file named once.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/errors.h"
#include "micro/sweep/sweep_plan.h"

namespace softglass::micro {
namespace {

TEST(SweepPlan, PaperPresetIsThePapersProtocol) {
  const SweepPlan plan = make_sweep_plan({.preset = "paper"});
  EXPECT_EQ(plan.particles, 1000u);
  EXPECT_EQ(plan.seeds.size(), 5u);
  EXPECT_EQ(plan.volume_fractions, (std::vector<double>{0.70, 0.75, 0.80, 0.85, 0.90}));
  ASSERT_FALSE(plan.gamma_tildes.empty());
  EXPECT_NEAR(std::log10(plan.gamma_tildes.front()), -9.0, 1e-12);
  EXPECT_NEAR(std::log10(plan.gamma_tildes.back()), -4.0, 1e-12);
  for (std::size_t k = 1; k < plan.gamma_tildes.size(); ++k)
    EXPECT_LE(std::log10(plan.gamma_tildes[k] / plan.gamma_tildes[k - 1]), 0.5 + 1e-12)
        << "at least two rates per decade";
  EXPECT_EQ(plan.cases.size(), 5u * 5u * plan.gamma_tildes.size());
}

TEST(SweepPlan, CasesOfOnePhiAndSeedShareTheirPacking) {
  const SweepPlan plan = make_sweep_plan({.preset = "fast", .packings = 2});
  EXPECT_EQ(plan.packings.size(), plan.volume_fractions.size() * 2);
  std::set<std::string> files;
  for (const SweepCase& c : plan.cases) {
    const SweepPacking& p = plan.packings.at(c.packing);
    EXPECT_EQ(p.volume_fraction, c.volume_fraction);
    EXPECT_EQ(p.seed, c.seed);
    EXPECT_TRUE(files.insert(c.file.string()).second) << "two cases write " << c.file;
  }
  for (const SweepPacking& p : plan.packings) EXPECT_TRUE(files.insert(p.file.string()).second);
}

TEST(SweepPlan, ExplicitListsOverrideThePreset) {
  const SweepPlan plan =
      make_sweep_plan({.preset = "standard", .volume_fractions = {0.85, 0.75}, .gamma_tildes = {1e-5}});
  EXPECT_EQ(plan.volume_fractions, (std::vector<double>{0.75, 0.85})) << "sorted";
  EXPECT_EQ(plan.gamma_tildes, std::vector<double>{1e-5});
  EXPECT_EQ(plan.particles, 1000u);
  EXPECT_EQ(plan.seeds.size(), 3u);
}

TEST(SweepPlan, RefusesIncompleteOrInvalidLists) {
  EXPECT_THROW(make_sweep_plan({.preset = "custom"}), InputError);
  EXPECT_THROW(make_sweep_plan({.preset = "slow"}), InputError);
  EXPECT_THROW(make_sweep_plan({.preset = "fast", .volume_fractions = {0.8, 0.8}}), InputError);
  EXPECT_THROW(make_sweep_plan({.preset = "fast", .volume_fractions = {0.5}}), InputError);
  EXPECT_THROW(make_sweep_plan({.preset = "fast", .gamma_tildes = {0.0}}), InputError);
  EXPECT_THROW(make_sweep_plan({.preset = "fast", .gamma_tildes = {std::nan("")}}), InputError);
}

}  // namespace
}  // namespace softglass::micro
