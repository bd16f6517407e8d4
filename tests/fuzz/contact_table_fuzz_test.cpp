// Fuzzing the contact-law table (`contact law = table`, micro/contact/laws/table.cpp):
// a text file of (deformation, reduced force) rows, interpolated as a power law
// between rows. An accepted table must never give NaN or a negative force.
#include <gtest/gtest.h>

#include <cmath>

#include "fuzz_check.h"
#include "micro/contact/contact_law.h"
#include "tests/common/test_files.h"

namespace softglass::micro {
namespace {

using namespace softglass::testing::fuzz;

// Deformations of a real packing, from barely touching to strongly squeezed.
// Far outside the table a steep law may overflow to inf or underflow to 0:
// that is the table's physics; NaN or a negative force never is.
void expect_valid(const ContactLaw& law, const std::string& input) {
  for (const double eps : {1e-6, 1e-3, 0.05, 0.3}) {
    EXPECT_GE(law.force(eps), 0.0) << "F(" << eps << ")\n" << input;
    EXPECT_FALSE(std::isnan(law.stiffness(eps))) << "F'(" << eps << ")\n" << input;
  }
}

TEST(ContactTableFuzz, RefusesOrReadsEveryMutation) {
  const std::string hertz = softglass::testing::read_text(
      std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" / "hertz_table.dat");
  const std::vector<std::string> seeds = {hertz, "0.01, 1e-3\n0.1, 4e-2\n0.2, 0.2\n"};
  fuzz_text(seeds, 11, 2000, [&](const std::string& text, const std::string& input) {
    ContactLawSpec spec;
    spec.name = "table";
    spec.table_text = text;
    spec.coefficients.set("file", "table.dat");
    return read_and_check(
        [&] { return make_contact_law(spec); },
        [&](const std::unique_ptr<ContactLaw>& law) { expect_valid(*law, input); }, input);
  });
}

}  // namespace
}  // namespace softglass::micro
