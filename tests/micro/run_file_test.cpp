// HDF5 run files (io/run_file.h): what is written is read back bit for bit.
#include <gtest/gtest.h>

#include <cstring>

#include "common/errors.h"
#include "common/h5_file.h"
#include "micro/contact/contact_law.h"
#include "micro/dynamics/integrator.h"
#include "micro/io/run_file.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// A real (small) record: a packing, its G0, and a short sheared run.
RunRecord small_record() {
  const PackingSpec spec = testing::small_packing_spec(8, 0.7);
  const auto law = testing::named_law("seth2011");
  Packing packing = make_packing(spec, law);

  RunRecord record = testing::packing_record(packing, law, spec.skin);
  // A non-zero strain with an integer part, so that its round trip is tested.
  record.packing_box.set_strain(2.375);

  testing::ShortShear run = testing::shear_briefly(packing, law, spec.skin, 0.3, 0.3);
  record.shear =
      ShearRecord{1e-4, std::move(run.result), std::move(run.final_particles), run.final_box};
  record.timings = {.packing = 1.5, .modulus = 0.25, .shear = 2.0, .total = 3.75, .threads = 2};
  return record;
}

TEST(RunFile, PackingAndTimeSeriesRoundTripExactly) {
  const RunRecord record = small_record();
  testing::TemporaryDirectory dir;
  const auto path = dir / "run.h5";
  write_run_file(path, record);

  // ---- packing
  const StoredPacking stored = read_packing(path);
  const Particles& p = record.packing_particles;
  ASSERT_EQ(stored.particles.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_TRUE(same_bits(stored.particles.position[i], p.position[i])) << "particle " << i;
    ASSERT_TRUE(same_bits(stored.particles.radius[i], p.radius[i])) << "particle " << i;
  }
  EXPECT_TRUE(same_bits(stored.box.side(), record.packing_box.side()));
  EXPECT_TRUE(same_bits(stored.box.strain(), record.packing_box.strain()));
  EXPECT_TRUE(same_bits(stored.box.image_offset(), record.packing_box.image_offset()));

  const PackingReport& a = stored.report;
  const PackingReport& b = record.packing;
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_TRUE(same_bits(a.volume_fraction, b.volume_fraction));
  EXPECT_TRUE(same_bits(a.side, b.side));
  EXPECT_TRUE(same_bits(a.coordination, b.coordination));
  EXPECT_TRUE(same_bits(a.coordination_nonrattler, b.coordination_nonrattler));
  EXPECT_EQ(a.rattlers, b.rattlers);
  EXPECT_TRUE(same_bits(a.mean_deformation, b.mean_deformation));
  EXPECT_TRUE(same_bits(a.max_deformation, b.max_deformation));
  EXPECT_TRUE(same_bits(a.pressure, b.pressure));
  EXPECT_TRUE(same_bits(a.energy_per_particle, b.energy_per_particle));
  EXPECT_TRUE(same_bits(a.residual, b.residual));
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.converged, b.converged);
  EXPECT_TRUE(same_bits(stored.modulus.modulus, record.modulus.modulus));
  EXPECT_TRUE(same_bits(stored.modulus.affine_modulus, record.modulus.affine_modulus));
  EXPECT_TRUE(same_bits(stored.modulus.solver_error, record.modulus.solver_error));

  // ---- time series
  const TimeSeries t = read_time_series(path);
  const TimeSeries& s = record.shear->result.series;
  ASSERT_EQ(t.size(), s.size());
  ASSERT_GT(s.size(), 20u);
  for (std::size_t k = 0; k < s.size(); ++k) {
    ASSERT_TRUE(same_bits(t.strain[k], s.strain[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(t.elastic[k], s.elastic[k])) << "sample " << k;  // row/column order too
    ASSERT_TRUE(same_bits(t.viscous[k], s.viscous[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(t.film[k], s.film[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(t.coordination[k], s.coordination[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(t.layering[k], s.layering[k])) << "sample " << k;
    ASSERT_TRUE(same_bits(t.step[k], s.step[k])) << "sample " << k;
  }
  // The viscous tensor is not symmetric: a transposition would be caught.
  EXPECT_NE(s.viscous.back()(0, 1), s.viscous.back()(1, 0));

  // ---- what has no reader in run_file.h, checked in the file directly
  const H5File file = H5File::open(path);
  const H5Group root = file.root();
  EXPECT_EQ(root.attribute_string("command"), "run");
  EXPECT_EQ(root.read_string("parameters"), record.parameters);
  const H5Group shear = root.group("shear");
  EXPECT_EQ(shear.read_scalar("gamma_tilde"), 1e-4);
  const H5Group configuration = shear.group("configuration");
  const H5Array position = configuration.read_array("position");
  const Particles& final_particles = record.shear->final_particles;
  ASSERT_EQ(position.dims, (std::vector<std::size_t>{final_particles.size(), 3}));
  for (std::size_t i = 0; i < final_particles.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_TRUE(same_bits(position.data[3 * i + c], final_particles.position[i][c]));
  EXPECT_EQ(configuration.read_scalar("strain"), record.shear->final_box.strain());
  const H5Group sigma = shear.group("summary").group("sigma");
  EXPECT_EQ(sigma.attribute_double("mean"), record.shear->result.summary["sigma"].mean);
  EXPECT_EQ(root.group("timings").read_scalar("total"), 3.75);
}

// /shear/counters: every counter under its name (docs/output.md), each given
// a different value here so that a swap of two would show.
TEST(RunFile, CountersAreWrittenUnderTheirNames) {
  RunRecord record = small_record();
  ShearCounters& c = record.shear->result.counters;
  c = {.steps = 101,
       .rejected_steps = 12,
       .evaluations = 103,
       .neighbour_builds = 104,
       .fixed_point_sweeps = 105,
       .newton_iterations = 106,
       .cg_iterations = 107,
       .smallest_step = 1e-6,
       .largest_step = 0.05,
       .rejected_error = 7,
       .rejected_list = 3,
       .rejected_solver = 2,
       .drag_freezes = 120,
       .minimiser = {.solves = 113,
                     .iterations = 114,
                     .cg_iterations = 115,
                     .force_evaluations = 116,
                     .assemblies = 117,
                     .damping_raises = 118,
                     .backtracks = 119}};
  testing::TemporaryDirectory dir;
  const auto path = dir / "run.h5";
  write_run_file(path, record);
  const H5File file = H5File::open(path);
  const H5Group g = file.root().group("shear").group("counters");
  const std::pair<const char*, std::size_t> counts[] = {{"steps", 101},
                                                        {"rejected_steps", 12},
                                                        {"evaluations", 103},
                                                        {"neighbour_builds", 104},
                                                        {"fixed_point_sweeps", 105},
                                                        {"newton_iterations", 106},
                                                        {"cg_iterations", 107},
                                                        {"rejected_error", 7},
                                                        {"rejected_list", 3},
                                                        {"rejected_solver", 2},
                                                        {"drag_freezes", 120},
                                                        {"minimiser_solves", 113},
                                                        {"minimiser_newton_iterations", 114},
                                                        {"minimiser_cg_iterations", 115},
                                                        {"minimiser_force_evaluations", 116},
                                                        {"minimiser_assemblies", 117},
                                                        {"minimiser_damping_raises", 118},
                                                        {"minimiser_backtracks", 119}};
  for (const auto& [name, value] : counts)
    EXPECT_EQ(g.attribute_int(name), static_cast<std::int64_t>(value)) << name;
  EXPECT_EQ(g.attribute_double("smallest_step"), 1e-6);
  EXPECT_EQ(g.attribute_double("largest_step"), 0.05);
}

TEST(RunFile, ReadingAMissingFileIsAnInputError) {
  testing::TemporaryDirectory dir;
  EXPECT_THROW(read_packing(dir / "absent.h5"), InputError);
  EXPECT_THROW(read_time_series(dir / "absent.h5"), InputError);
}

TEST(RunFile, PackOnlyFileHasNoTimeSeries) {
  // A `pack` record has no /shear group: reading a time series is an InputError
  // naming what is missing, not a crash.
  RunRecord record;
  record.command = "pack";
  record.packing_particles = Particles({Vec3(1, 2, 3), Vec3(4, 5, 6)}, {1.0, 1.1});
  record.packing_box = LeesEdwardsBox(12.0);
  record.packing.particles = 2;
  testing::TemporaryDirectory dir;
  write_run_file(dir / "pack.h5", record);
  EXPECT_EQ(read_packing(dir / "pack.h5").particles.size(), 2u);
  EXPECT_THROW(read_time_series(dir / "pack.h5"), InputError);
}

}  // namespace
}  // namespace softglass::micro
