// Fuzzing the checkpoint reader (micro/io/checkpoint_file.h) with damaged
// copies of a checkpoint written by a real run. A run resumes from what it
// returns, so every number must be finite and every array consistent.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "h5_mutation.h"
#include "micro_seed_files.h"

namespace softglass::micro {
namespace {

using namespace softglass::testing::fuzz;

void expect_valid(const ShearCheckpoint& c, const std::string& input) {
  const Particles& p = c.particles;
  for (const auto* vectors : {&p.position, &p.velocity})
    for (const Vec3& x : *vectors) expect_all_finite(x, "a position or velocity", input);
  expect_all_finite(p.radius, "a radius", input);
  for (const double r : p.radius) EXPECT_GT(r, 0.0) << "radius\n" << input;
  EXPECT_EQ(p.radius.size(), p.position.size()) << input;
  EXPECT_EQ(p.velocity.size(), p.position.size()) << input;
  // Labels index the particles: a permutation of 0 … N-1.
  std::vector<std::uint32_t> labels = p.label, identity(p.size());
  std::sort(labels.begin(), labels.end());
  std::iota(identity.begin(), identity.end(), 0u);
  EXPECT_EQ(labels, identity) << "labels\n" << input;
  expect_all_finite(
      std::vector{c.box.strain(), c.start, c.next_sample, c.next_check, c.next_snapshot, c.seconds,
                  c.counters.smallest_step, c.counters.largest_step},
      "the state", input);
  EXPECT_FALSE(std::isnan(c.worst)) << input;  // inf before the first check
  expect_all_finite(c.series.strain, "series strain", input);
  for (const auto* tensors : {&c.series.elastic, &c.series.viscous, &c.series.film})
    for (const Eigen::Matrix3d& s : *tensors) expect_all_finite(s.reshaped(), "a stress", input);
  for (const Snapshot& snap : c.snapshots) {
    expect_finite(snap.strain, "a snapshot strain", input);
    for (const Vec3& x : snap.position) expect_all_finite(x, "a snapshot position", input);
  }
}

TEST(CheckpointFileFuzz, RefusesOrReadsEveryDamage) {
  softglass::testing::TemporaryDirectory dir;
  const auto seed = testing::write_seed_files(dir.path()).checkpoint;
  fuzz_h5(seed, dir / "damaged.h5", 31, 300,
          [](const std::filesystem::path& file, const std::string& input) {
            return read_and_check([&] { return read_checkpoint(file); },
                                  [&](const ShearCheckpoint& c) { expect_valid(c, input); }, input);
          });
}

}  // namespace
}  // namespace softglass::micro
