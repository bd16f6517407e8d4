// Fuzzing the readers of micro run files (micro/io/run_file.h) with damaged
// copies of a file written by write_run_file. Whatever they return is used to
// compute with (a packing sheared again, a series analysed again, a flow-curve
// table), so it must be finite and consistent.
#include <gtest/gtest.h>

#include "h5_mutation.h"
#include "micro_seed_files.h"

namespace softglass::micro {
namespace {

using namespace softglass::testing::fuzz;
using softglass::testing::TemporaryDirectory;

void expect_valid(const Particles& p, const LeesEdwardsBox& box, const std::string& input) {
  for (const Vec3& x : p.position) expect_all_finite(x, "a position", input);
  expect_all_finite(p.radius, "a radius", input);
  for (const double r : p.radius) EXPECT_GT(r, 0.0) << "radius\n" << input;
  expect_finite(box.strain(), "the strain", input);
  EXPECT_EQ(p.radius.size(), p.position.size()) << input;
}

void expect_valid(const TimeSeries& t, const std::string& input) {
  expect_all_finite(t.strain, "strain", input);
  expect_all_finite(t.coordination, "coordination", input);
  expect_all_finite(t.layering, "layering", input);
  expect_all_finite(t.step, "step", input);
  for (const auto* tensors : {&t.elastic, &t.viscous, &t.film})
    for (const Eigen::Matrix3d& s : *tensors) expect_all_finite(s.reshaped(), "a stress", input);
  EXPECT_EQ(t.coordination.size(), t.size()) << input;
  EXPECT_EQ(t.elastic.size(), t.size()) << input;
}

void expect_valid(const StoredRunSummary& s, const std::string& input) {
  expect_all_finite(std::vector{s.gamma_tilde, s.volume_fraction, s.shear_modulus,
                                s.averaged_strain, s.coordination, s.layering},
                    "a summary value", input);
  for (const ObservableEstimate& o : s.observables) {
    expect_all_finite(std::vector{o.estimate.mean, o.estimate.standard_error}, o.name, input);
    EXPECT_GE(o.estimate.standard_error, 0.0) << o.name << "\n" << input;
  }
  for (const auto* e : {&s.r_m, &s.f_m})
    if (*e) expect_all_finite(std::vector{(*e)->value, (*e)->error}, "r_m or f_m", input);
}

void expect_valid(const StoredPacking& s, const std::string& input) {
  expect_valid(s.particles, s.box, input);
}

void expect_valid(const StoredSnapshots& s, const std::string& input) {
  expect_all_finite(s.radius, "a radius", input);
  expect_finite(s.side, "the side", input);
  for (const Snapshot& snap : s.snapshots) {
    expect_finite(snap.strain, "a snapshot strain", input);
    for (const Vec3& x : snap.position) expect_all_finite(x, "a snapshot position", input);
    EXPECT_EQ(snap.position.size(), s.radius.size()) << input;
  }
}

// Each test (a process of its own under CTest) makes its seed file, then
// gives `read` its damaged copies and checks what it returns.
class RunFileFuzz : public ::testing::Test {
 protected:
  template <class Read>
  void fuzz(std::uint64_t seed, Read read) {
    fuzz_h5(seed_, dir_ / "damaged.h5", seed, 150,
            [&](const std::filesystem::path& file, const std::string& input) {
              return read_and_check([&] { return read(file); },
                                    [&](const auto& value) { expect_valid(value, input); }, input);
            });
  }

  TemporaryDirectory dir_;
  const std::filesystem::path seed_ = testing::write_seed_files(dir_.path()).run;
};

// Each reader as a lambda: read_time_series is overloaded.
TEST_F(RunFileFuzz, ReadPackingRefusesOrReadsEveryDamage) {
  fuzz(21, [](const std::filesystem::path& f) { return read_packing(f); });
}

TEST_F(RunFileFuzz, ReadTimeSeriesRefusesOrReadsEveryDamage) {
  fuzz(22, [](const std::filesystem::path& f) { return read_time_series(f); });
}

TEST_F(RunFileFuzz, ReadRunSummaryRefusesOrReadsEveryDamage) {
  fuzz(23, [](const std::filesystem::path& f) { return read_run_summary(f); });
}

TEST_F(RunFileFuzz, ReadStationarySnapshotsRefusesOrReadsEveryDamage) {
  fuzz(24, [](const std::filesystem::path& f) { return read_stationary_snapshots(f); });
}

}  // namespace
}  // namespace softglass::micro
