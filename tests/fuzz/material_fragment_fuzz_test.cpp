// Fuzzing the macro material fragment reader (macro/material/material_parameters.h)
// with mutations of the fragment of cases/ and of one with every entry set.
#include <gtest/gtest.h>

#include "fuzz_check.h"
#include "macro/material/material_parameters.h"
#include "tests/common/test_files.h"

namespace softglass::macro {
namespace {

using namespace softglass::testing::fuzz;

void expect_valid(const Material& m, const std::string& input) {
  const ShearLaw& s = *m.shear;
  // At 1/s every power law is its coefficient: finite whatever the index.
  const std::vector<double> values{s.yield_stress(), s.stress(1.0),
                                   m.first_normal_stress_difference->value(1.0),
                                   m.second_normal_stress_difference->value(1.0)};
  expect_all_finite(values, "the material's stresses", input);
  EXPECT_GE(s.yield_stress(), 0.0) << input;
  EXPECT_GT(s.excess_stress(1.0), 0.0) << input;
}

TEST(MaterialFragmentFuzz, RefusesOrReadsEveryMutation) {
  const std::string full =
      "subsection material\n  set model = herschel-bulkley\n  set yield stress = 12.5\n"
      "  set consistency = 3.1\n  set flow index = 0.5\n  set N1 yield = 2\n"
      "  set N1 consistency = 0.4\n  set N1 flow index = 0.6\n  set N2 yield = -0.5\n"
      "  set N2 consistency = -0.1\n  set N2 flow index = 0.6\nend\n";
  const std::vector<std::string> seeds = {
      softglass::testing::read_text(std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" /
                                    "macro_material_castoroil85.prm"),
      full};
  fuzz_text(seeds, 71, 2000, [](const std::string& text, const std::string& input) {
    return read_and_check([&] { return parse_material(text, "material.prm"); },
                          [&](const Material& m) { expect_valid(m, input); }, input);
  });
}

}  // namespace
}  // namespace softglass::macro
