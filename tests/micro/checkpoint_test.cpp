// Checkpoints of a running shear: a run interrupted at a checkpoint and resumed
// from its file — a new process would do exactly this — goes on bit for bit
// like the uninterrupted run, because both start afresh from the same stored
// state at every checkpoint (protocol/shear_run.h).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
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
    model.gamma_tilde = gamma_tilde_;
    OverdampedShear flow(ContactSystem(packing_.particles, packing_.box, law_, spec_.skin), model);
    const auto integrator = make_integrator(scheme_);
    ShearCheckpointing checkpointing{150, save, [&] { return make_integrator(scheme_); },
                                     resume_from};
    return run_shear(flow, *integrator, protocol_, {}, checkpointing);
  }

  // Runs with checkpoints, killed right after writing the second to `file`;
  // returns what it wrote there.
  ShearCheckpoint interrupted_at_second_checkpoint(const std::filesystem::path& file) {
    ShearCheckpoint last;
    int written = 0;
    EXPECT_THROW(shear([&](const ShearCheckpoint& c) {
                   write_checkpoint(file, c);
                   last = c;
                   if (++written == 2) throw Interrupted();
                 }),
                 Interrupted);
    return last;
  }

  // A run killed right after its second checkpoint and resumed from it gives
  // the uninterrupted run's series, snapshots and counters; returns the latter.
  ShearResult expect_resumed_run_bit_identical() {
    int saved = 0;
    const ShearResult whole = shear([&](const ShearCheckpoint&) { ++saved; });
    EXPECT_GE(saved, 3) << "the run must pass several checkpoints";

    // The same run, killed right after writing its second checkpoint.
    const std::filesystem::path file = dir_.path() / "run.checkpoint.h5";
    interrupted_at_second_checkpoint(file);
    const ShearCheckpoint stored = read_checkpoint(file);
    EXPECT_GT(stored.series.size(), 0u);
    const ShearResult resumed = shear({}, &stored);

    const TimeSeries& a = whole.series;
    const TimeSeries& b = resumed.series;
    EXPECT_EQ(a.size(), b.size());
    std::size_t differing_samples = 0, differing_positions = 0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
      differing_samples += a.strain[k] != b.strain[k] || !same_bits(a.elastic[k], b.elastic[k]) ||
                           !same_bits(a.viscous[k], b.viscous[k]) ||
                           a.coordination[k] != b.coordination[k];
    EXPECT_EQ(differing_samples, 0u);
    EXPECT_EQ(whole.snapshots.size(), resumed.snapshots.size());
    for (std::size_t k = 0; k < std::min(whole.snapshots.size(), resumed.snapshots.size()); ++k)
      for (std::size_t i = 0; i < whole.snapshots[k].position.size(); ++i)
        differing_positions += whole.snapshots[k].position[i] != resumed.snapshots[k].position[i];
    EXPECT_EQ(differing_positions, 0u);
    EXPECT_EQ(whole.summary["sigma"].mean, resumed.summary["sigma"].mean);
    EXPECT_EQ(whole.counters, resumed.counters) << "the counters carry over";
    return whole;
  }

  std::shared_ptr<const ContactLaw> law_ = testing::named_law("seth2011");
  IntegratorSpec scheme_{.name = "euler"};
  double gamma_tilde_ = 1e-4;
  PackingSpec spec_;
  Packing packing_;
  ShearProtocol protocol_;
  testing::TemporaryDirectory dir_;
};

TEST_F(Checkpoints, ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  const ShearResult whole = expect_resumed_run_bit_identical();
  // `euler` rejects a step for its error only.
  EXPECT_EQ(whole.counters.rejected_error, whole.counters.rejected_steps);
  EXPECT_EQ(whole.counters.minimiser, IncrementalCounters{});
}

// BDF2 keeps a step of history, which a checkpoint does not store: both runs
// start each checkpoint interval with a fresh integrator (one backward-Euler
// step), so they still agree bit for bit.
TEST_F(Checkpoints, Bdf2ResumedRunIsBitIdenticalToTheUninterruptedOne) {
  scheme_ = {.name = "bdf2", .tolerance = 1e-3};
  gamma_tilde_ = 1e-6;
  protocol_.min_strain = protocol_.max_strain = 1.0;
  expect_resumed_run_bit_identical();
}

// The implicit step's counters (integrator.h, incremental_counters.h) add up:
// every step tried is one solve, and every rejected one has one cause. A
// checkpoint stores them and reads them back exactly, a resumed run carries
// them over, and a checkpoint written before they were stored (9 counters)
// still resumes the same run, counting them from the resumption on.
TEST_F(Checkpoints, ImplicitStepCountersAddUpAndCarryOver) {
  scheme_ = {.name = "implicit", .tolerance = 1e-3};
  gamma_tilde_ = 1e-6;
  protocol_.min_strain = protocol_.max_strain = 1.0;
  const ShearResult whole = shear({});
  const ShearCounters& c = whole.counters;
  std::printf(
      "[ measured ] implicit, 1 strain: %zu steps, %zu rejected (%zu error, %zu list, %zu "
      "solver), %zu drag freezes, %zu solves, %zu Newton, %zu CG, %zu evaluations, %zu damping "
      "raises, %zu backtracks\n",
      c.steps, c.rejected_steps, c.rejected_error, c.rejected_list, c.rejected_solver,
      c.drag_freezes, c.minimiser.solves, c.minimiser.iterations, c.minimiser.cg_iterations,
      c.minimiser.force_evaluations, c.minimiser.damping_raises, c.minimiser.backtracks);
  ASSERT_GT(c.rejected_steps, 0u) << "the identities below need rejections";
  EXPECT_EQ(c.rejected_error + c.rejected_list + c.rejected_solver, c.rejected_steps);
  EXPECT_EQ(c.minimiser.solves, c.steps + c.rejected_steps);
  // One frozen drag per step at least; a retry mostly keeps its step's.
  EXPECT_GE(c.drag_freezes, c.steps);
  EXPECT_LT(c.drag_freezes, c.minimiser.solves);
  // A solve evaluates its guess and every Newton iteration at least one trial,
  // but a guess beyond the neighbour list's reach is not evaluated (a list
  // rejection).
  EXPECT_GE(c.minimiser.force_evaluations + c.rejected_list,
            c.minimiser.solves + c.minimiser.iterations);
  EXPECT_LE(c.minimiser.assemblies, c.minimiser.iterations);
  EXPECT_GT(c.minimiser.cg_iterations, c.minimiser.iterations);

  const std::filesystem::path file = dir_.path() / "implicit.checkpoint.h5";
  const ShearCheckpoint written = interrupted_at_second_checkpoint(file);
  const ShearCheckpoint stored = read_checkpoint(file);
  EXPECT_GT(stored.counters.minimiser.solves, 0u);
  EXPECT_EQ(stored.counters, written.counters) << "written and read back exactly";
  const ShearResult resumed = shear({}, &stored);
  EXPECT_EQ(resumed.counters, whole.counters);

  testing::keep_older_counters(file, 9);
  const ShearCheckpoint older = read_checkpoint(file);
  EXPECT_EQ(older.counters.steps, stored.counters.steps);
  EXPECT_EQ(older.counters.rejected_steps, stored.counters.rejected_steps);
  EXPECT_EQ(older.counters.rejected_error, 0u);
  EXPECT_EQ(older.counters.minimiser, IncrementalCounters{});
  const ShearResult from_older = shear({}, &older);
  ASSERT_EQ(from_older.series.size(), whole.series.size());
  for (std::size_t k = 0; k < whole.series.size(); ++k)
    ASSERT_TRUE(same_bits(from_older.series.elastic[k], whole.series.elastic[k])) << k;
  EXPECT_EQ(from_older.counters.steps, whole.counters.steps);
  EXPECT_EQ(from_older.counters.rejected_steps, whole.counters.rejected_steps);
  EXPECT_EQ(from_older.counters.minimiser.solves + stored.counters.minimiser.solves,
            whole.counters.minimiser.solves);
  EXPECT_EQ(from_older.counters.rejected_error + stored.counters.rejected_error,
            whole.counters.rejected_error);
}

TEST_F(Checkpoints, RefusesCountersOfAnUnknownLength) {
  const std::filesystem::path file = dir_.path() / "run.checkpoint.h5";
  interrupted_at_second_checkpoint(file);
  testing::keep_older_counters(file, 12);
  EXPECT_THROW(read_checkpoint(file), InputError);
}

TEST_F(Checkpoints, RefusesAFileThatIsNotACheckpoint) {
  const std::filesystem::path file = dir_.path() / "text.h5";
  testing::write_text(file, "not HDF5");
  EXPECT_THROW(read_checkpoint(file), InputError);
}

}  // namespace
}  // namespace softglass::micro
