// The quasi-static run (protocol/quasi_static_run.h): a sheared run's series,
// stopping rule and snapshots from AQS strain steps, and checkpoints that a
// run resumed from — read back from its file, as a new process would — goes on
// from bit for bit like the uninterrupted run.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <stdexcept>

#include "common/errors.h"
#include "micro/io/checkpoint_file.h"
#include "micro/protocol/quasi_static_run.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

class QuasiStaticRun : public ::testing::Test {
 protected:
  void SetUp() override {
    omp_set_num_threads(1);
    spec_.particles = 128;  // the fewest the neighbour grid takes with this skin at φ = 0.8
    spec_.volume_fraction = 0.8;
    spec_.skin = 0.3;
    spec_.seed = 4;
    packing_ = make_packing(spec_, law_);
    settings_.strain_step = 1e-3;
    protocol_.min_strain = protocol_.max_strain = 0.4;
    protocol_.min_stationary_strain = 0.2;
    protocol_.check_interval = 0.2;
    protocol_.snapshot_interval = 0.05;
  }

  QuasiStaticResult shear(const QuasiStaticCheckpointing& checkpointing = {}) const {
    return run_quasi_static(packing_.particles, packing_.box, law_, spec_.skin, settings_,
                            protocol_, {}, checkpointing);
  }

  std::shared_ptr<const ContactLaw> law_ = testing::named_law("seth2011");
  PackingSpec spec_;
  Packing packing_;
  QuasiStaticSettings settings_;
  ShearProtocol protocol_;
  testing::TemporaryDirectory dir_;
};

// Samples every sample interval, each the mean of its 10 steps; σ^v = 0; one
// snapshot per snapshot interval; unconverged at max strain for a target no
// run of 0.4 strain meets.
TEST_F(QuasiStaticRun, SamplesItsStepsLikeAShearedRun) {
  protocol_.target_relative_error = 1e-6;
  const QuasiStaticResult r = shear();
  const TimeSeries& series = r.run.series;
  ASSERT_EQ(series.size(), 40u);
  EXPECT_NEAR(series.strain.front(), 0.01, 1e-12);
  EXPECT_NEAR(series.strain.back(), 0.4, 1e-12);
  for (std::size_t k = 0; k < series.size(); ++k) EXPECT_TRUE(series.viscous[k].isZero(0.0));
  EXPECT_EQ(r.run.snapshots.size(), 8u);
  EXPECT_EQ(r.run.counters.steps, 400u);
  EXPECT_GE(r.run.counters.newton_iterations, r.run.counters.steps);
  // The minimisations' counters: at least one solve per step (more after a
  // list rebuild), and the Newton and CG counts are theirs.
  const IncrementalCounters& m = r.run.counters.minimiser;
  EXPECT_GE(m.solves, r.run.counters.steps);
  EXPECT_EQ(m.iterations, r.run.counters.newton_iterations);
  EXPECT_EQ(m.cg_iterations, r.run.counters.cg_iterations);
  EXPECT_GT(m.force_evaluations, m.iterations);
  EXPECT_LE(m.assemblies, m.iterations);
  EXPECT_EQ(r.unconverged_steps, 0u);
  EXPECT_GT(r.stress_drops, 0u);
  EXPECT_FALSE(r.run.converged);
  EXPECT_NE(r.run.stop_reason.find("maximum strain 0.4"), std::string::npos) << r.run.stop_reason;
  EXPECT_GT(r.run.summary["sigma"].mean, 0.0);
  EXPECT_EQ(r.run.summary["sigma_viscous"].mean, 0.0);
  EXPECT_NEAR(r.final_box.strain(), 0.4, 1e-12);
}

TEST_F(QuasiStaticRun, ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  int saved = 0;
  const QuasiStaticResult whole =
      shear({.every_steps = 100, .save = [&](const auto&) { ++saved; }});
  ASSERT_GE(saved, 3) << "the run must pass several checkpoints";

  // The same run, killed right after writing its second checkpoint.
  const std::filesystem::path file = dir_.path() / "aqs.checkpoint.h5";
  int written = 0;
  EXPECT_THROW(shear({.every_steps = 100,
                      .save =
                          [&](const QuasiStaticCheckpoint& c) {
                            write_checkpoint(file, c);
                            if (++written == 2) throw Interrupted();
                          }}),
               Interrupted);
  const QuasiStaticCheckpoint stored = read_quasi_static_checkpoint(file);
  ASSERT_GT(stored.series.size(), 0u);
  EXPECT_GT(stored.counters.minimiser.solves, 0u) << "the minimiser's counters are stored";
  EXPECT_THROW(read_checkpoint(file), InputError) << "not a sheared run's checkpoint";
  EXPECT_NEAR(strain_step_of(stored), settings_.strain_step, 1e-9 * settings_.strain_step)
      << "the step it was made at: its strain over its steps";
  const QuasiStaticResult resumed = shear({.resume_from = &stored});

  const TimeSeries& a = whole.run.series;
  const TimeSeries& b = resumed.run.series;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a.strain[k], b.strain[k]) << "sample " << k;
    ASSERT_EQ(std::memcmp(a.elastic[k].data(), b.elastic[k].data(), sizeof(double) * 9), 0)
        << "sample " << k;
    ASSERT_EQ(a.coordination[k], b.coordination[k]) << "sample " << k;
  }
  ASSERT_EQ(whole.run.snapshots.size(), resumed.run.snapshots.size());
  for (std::size_t k = 0; k < whole.run.snapshots.size(); ++k)
    ASSERT_EQ(whole.run.snapshots[k].position, resumed.run.snapshots[k].position);
  EXPECT_EQ(whole.run.summary["sigma"].mean, resumed.run.summary["sigma"].mean);
  EXPECT_EQ(whole.run.counters.steps, resumed.run.counters.steps) << "the counters carry over";
  EXPECT_EQ(whole.run.counters.newton_iterations, resumed.run.counters.newton_iterations);
  EXPECT_EQ(whole.run.counters.minimiser, resumed.run.counters.minimiser);
  EXPECT_EQ(whole.stress_drops, resumed.stress_drops);
  EXPECT_EQ(whole.final_particles.position, resumed.final_particles.position);

  // A checkpoint from before the minimiser's counters were stored (5
  // counters) resumes the same run; those counters start at the resumption.
  testing::keep_older_counters(file, 5);
  const QuasiStaticCheckpoint older = read_quasi_static_checkpoint(file);
  EXPECT_EQ(older.counters.minimiser, IncrementalCounters{});
  const QuasiStaticResult from_older = shear({.resume_from = &older});
  EXPECT_EQ(from_older.run.summary["sigma"].mean, whole.run.summary["sigma"].mean);
  EXPECT_EQ(from_older.run.counters.newton_iterations, whole.run.counters.newton_iterations);
  EXPECT_EQ(from_older.run.counters.minimiser.solves + stored.counters.minimiser.solves,
            whole.run.counters.minimiser.solves);
}

}  // namespace
}  // namespace softglass::micro
