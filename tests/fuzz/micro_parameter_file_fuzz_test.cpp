// Fuzzing the micro parameter and sweep files (micro/input/parameter_file.h):
// mutations of the cases and of the full template, read in-process.
#include <gtest/gtest.h>

#include "fuzz_check.h"
#include "micro/input/parameter_file.h"
#include "tests/common/test_files.h"

namespace softglass::micro {
namespace {

using namespace softglass::testing::fuzz;
using softglass::testing::read_text;
using softglass::testing::TemporaryDirectory;
using softglass::testing::write_text;

std::string case_file(const std::string& name) {
  return read_text(std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" / name);
}

// Every number the engine takes from the file: checked finite here, while the
// reader is trusted with their ranges (its patterns state them).
void expect_valid(const MicroParameters& p, const std::string& input) {
  const double values[] = {p.packing.volume_fraction,
                           p.packing.initial_volume_fraction,
                           p.packing.compression_step,
                           p.packing.stage_tolerance,
                           p.packing.relaxation.force_tolerance,
                           p.packing.radii.polydispersity,
                           p.packing.radii.truncation_sigmas,
                           p.packing.skin,
                           p.shear_model.gamma_tilde,
                           p.shear_model.mobility_factor,
                           p.shear_model.drag.tolerance,
                           p.protocol.sample_interval,
                           p.protocol.check_interval,
                           p.protocol.min_strain,
                           p.protocol.max_strain,
                           p.protocol.min_stationary_strain,
                           p.protocol.snapshot_interval,
                           p.protocol.target_relative_error,
                           p.integrator.tolerance,
                           p.integrator.stability_fraction,
                           p.integrator.max_step,
                           p.integrator.solver_tolerance,
                           p.structure.bin_width,
                           p.structure.range,
                           p.structure.slab,
                           p.structure.map_bin_width};
  expect_all_finite(values, "a parameter", input);
  EXPECT_GE(p.packing.particles, 2u) << input;
  EXPECT_LE(p.protocol.min_strain, p.protocol.max_strain) << input;
  EXPECT_FALSE(p.output_file.empty()) << input;
}

TEST(MicroParameterFileFuzz, RefusesOrReadsEveryMutation) {
  TemporaryDirectory dir;
  const auto file = dir / "case.prm";
  const std::vector<std::string> seeds = {case_file("pack_phi080.prm"), case_file("demo.prm"),
                                          case_file("run_phi080_1e-4.prm"), parameter_template()};
  fuzz_text(seeds, 7, 400, [&](const std::string& text, const std::string& input) {
    write_text(file, text);
    return read_and_check([&] { return read_parameter_file(file); },
                          [&](const MicroParameters& p) { expect_valid(p, input); }, input);
  });
}

TEST(MicroParameterFileFuzz, RefusesOrReadsEveryMutatedSweepFile) {
  TemporaryDirectory dir;
  const auto file = dir / "sweep.prm";
  const std::vector<std::string> seeds = {case_file("sweep_fast_two_packings.prm"),
                                          case_file("sweep_fast_low_rates.prm"),
                                          parameter_template(TemplateKind::sweep)};
  fuzz_text(seeds, 8, 300, [&](const std::string& text, const std::string& input) {
    write_text(file, text);
    return read_and_check([&] { return read_sweep_file(file); },
                          [&](const SweepParameters& s) {
                            expect_valid(s.base, input);
                            expect_all_finite(s.spec.volume_fractions, "sweep volume fractions",
                                              input);
                            expect_all_finite(s.spec.gamma_tildes, "sweep gamma dot tildes", input);
                            EXPECT_FALSE(s.spec.directory.empty()) << input;
                          },
                          input);
  });
}

}  // namespace
}  // namespace softglass::micro
