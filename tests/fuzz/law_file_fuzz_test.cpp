// Fuzzing the law-file reader (bridge/app/law_file.h) with mutations of the
// law files of cases/. `bridge material` and `bridge rescale` compute with
// every number of an accepted law, so each must be finite.
#include <gtest/gtest.h>

#include "bridge/app/law_file.h"
#include "fuzz_check.h"
#include "tests/common/test_files.h"

namespace softglass::bridge {
namespace {

using namespace softglass::testing::fuzz;
using softglass::testing::read_text;
using softglass::testing::write_text;

void expect_finite(const std::vector<Estimate>& list, const std::string& name,
                   const std::string& input) {
  for (const Estimate& e : list) expect_all_finite(std::vector{e.value, e.error}, name, input);
}

void expect_valid(const Law& law, const std::string& input) {
  expect_all_finite(law.phi, "volume fractions", input);
  expect_all_finite(std::vector{law.gamma_tilde_min, law.gamma_tilde_max}, "gamma tilde range",
                    input);
  expect_finite(law.modulus, "shear modulus", input);
  expect_finite(law.yield_strain, "yield strain", input);
  for (const auto& hb : law.hb) {
    if (!hb) continue;
    expect_finite(hb->yield, "yield", input);
    expect_finite(hb->consistency, "consistency", input);
    expect_finite(hb->exponent, "exponent", input);
    expect_all_finite(hb->correlation, "correlation", input);
  }
  if (law.force) {
    expect_finite(law.force->yield, "f_y", input);
    expect_finite(law.force->slope, "k_f", input);
  }
  for (const auto& k : law.k)
    if (k) expect_all_finite(std::vector{k->value, k->error}, "k", input);
  expect_all_finite(std::vector{law.mean_exponent.value, law.mean_exponent.error}, "mean exponent",
                    input);
}

TEST(LawFileFuzz, RefusesOrReadsEveryMutation) {
  softglass::testing::TemporaryDirectory dir;
  const auto file = dir / "law.prm";
  const auto cases = std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases";
  const std::vector<std::string> seeds = {read_text(cases / "bridge_synthetic_law.prm"),
                                          read_text(cases / "bridge_law_paper_sweep.prm")};
  fuzz_text(seeds, 61, 400, [&](const std::string& text, const std::string& input) {
    write_text(file, text);
    return read_and_check([&] { return read_law_file(file); },
                          [&](const Law& law) { expect_valid(law, input); }, input);
  });
}

}  // namespace
}  // namespace softglass::bridge
