// Checkpoints of a running shear: a run interrupted at a checkpoint and resumed
// from its file — a new process would do exactly this — goes on bit for bit
// like the uninterrupted run, because both start afresh from the same stored
// state at every checkpoint (protocol/shear_run.h).
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <stdexcept>

#include "common/errors.h"
#include "micro/io/checkpoint_file.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

bool same_bits(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 9) == 0;
}

class Checkpoints : public ::testing::Test {
 protected:
  void SetUp() override {
    omp_set_num_threads(1);
    spec_.particles = 200;
    spec_.volume_fraction = 0.8;
    spec_.skin = 0.3;
    spec_.seed = 9;
    packing_ = make_packing(spec_, law_);
    protocol_.min_strain = protocol_.max_strain = 1.5;
    protocol_.min_stationary_strain = 0.5;
    protocol_.check_interval = 0.5;
    protocol_.snapshot_interval = 0.1;
  }

  // Shears the packing with checkpoints every 150 steps; `save` sees each one.
  ShearResult shear(const std::function<void(const ShearCheckpoint&)>& save,
                    const ShearCheckpoint* resume_from = nullptr) {
    ShearModel model;
    model.gamma_tilde = 1e-4;
    OverdampedShear flow(ContactSystem(packing_.particles, packing_.box, law_, spec_.skin), model);
    const auto integrator = make_integrator({.name = "euler"});
    ShearCheckpointing checkpointing{150, save, [] { return make_integrator({.name = "euler"}); },
                                     resume_from};
    return run_shear(flow, *integrator, protocol_, {}, checkpointing);
  }

  std::shared_ptr<const ContactLaw> law_ = testing::named_law("seth2011");
  PackingSpec spec_;
  Packing packing_;
  ShearProtocol protocol_;
  testing::TemporaryDirectory dir_;
};

TEST_F(Checkpoints, ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  int saved = 0;
  const ShearResult whole = shear([&](const ShearCheckpoint&) { ++saved; });
  ASSERT_GE(saved, 3) << "the run must pass several checkpoints";

  // The same run, killed right after writing its second checkpoint.
  const std::filesystem::path file = dir_.path() / "run.checkpoint.h5";
  int written = 0;
  EXPECT_THROW(shear([&](const ShearCheckpoint& c) {
                 write_checkpoint(file, c);
                 if (++written == 2) throw Interrupted();
               }),
               Interrupted);
  const ShearCheckpoint stored = read_checkpoint(file);
  ASSERT_GT(stored.series.size(), 0u);
  const ShearResult resumed = shear({}, &stored);

  const TimeSeries& a = whole.series;
  const TimeSeries& b = resumed.series;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a.strain[k], b.strain[k]) << "sample " << k;
    ASSERT_TRUE(same_bits(a.elastic[k], b.elastic[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(a.viscous[k], b.viscous[k])) << "sample " << k;
    ASSERT_EQ(a.coordination[k], b.coordination[k]) << "sample " << k;
  }
  ASSERT_EQ(whole.snapshots.size(), resumed.snapshots.size());
  for (std::size_t k = 0; k < whole.snapshots.size(); ++k)
    for (std::size_t i = 0; i < whole.snapshots[k].position.size(); ++i)
      ASSERT_EQ(whole.snapshots[k].position[i], resumed.snapshots[k].position[i]);
  EXPECT_EQ(whole.summary["sigma"].mean, resumed.summary["sigma"].mean);
  EXPECT_EQ(whole.counters.steps, resumed.counters.steps) << "the counters carry over";
  EXPECT_EQ(whole.counters.evaluations, resumed.counters.evaluations);
}

TEST_F(Checkpoints, RefusesAFileThatIsNotACheckpoint) {
  const std::filesystem::path file = dir_.path() / "text.h5";
  testing::write_text(file, "not HDF5");
  EXPECT_THROW(read_checkpoint(file), InputError);
}

}  // namespace
}  // namespace softglass::micro
