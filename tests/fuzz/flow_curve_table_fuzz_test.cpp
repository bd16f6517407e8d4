// Fuzzing the bridge's flow-curve tables (bridge/io/flow_curve_table.h): the
// table, its per-packing companion and a structure table merged into it, each
// parsed by CsvTable from a mutated text. What is accepted is fitted, so every
// value must be finite and obey the documented rules.
#include <gtest/gtest.h>

#include "bridge/io/flow_curve_table.h"
#include "fuzz_check.h"
#include "tests/common/test_files.h"

namespace softglass::bridge {
namespace {

using namespace softglass::testing::fuzz;

std::string case_file(const std::string& name) {
  return softglass::testing::read_text(std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" /
                                       name);
}

void expect_valid(const StatePoint& p, const std::string& input) {
  EXPECT_TRUE(p.phi > 0 && p.phi < 1) << "phi = " << p.phi << "\n" << input;
  // γ̃ = 0: a quasi-static row.
  EXPECT_TRUE(std::isfinite(p.gamma_tilde) && p.gamma_tilde >= 0) << p.gamma_tilde << "\n" << input;
  EXPECT_GE(p.packings, 1u) << input;
  expect_all_finite(std::vector{p.modulus.value, p.modulus.error}, "G0", input);
  for (Quantity q : kAllQuantities) {
    if (!p.values[index(q)]) continue;
    const Estimate& e = *p.values[index(q)];
    expect_all_finite(std::vector{e.value, e.error}, column_name(q), input);
    EXPECT_GT(e.error, 0.0) << column_name(q) << "\n" << input;
  }
}

void expect_valid(const FlowCurveTable& table, const std::string& input) {
  EXPECT_FALSE(table.points.empty()) << input;
  for (const StatePoint& p : table.points) expect_valid(p, input);
}

void expect_valid(const std::vector<PackingRun>& runs, const std::string& input) {
  for (const PackingRun& r : runs) {
    EXPECT_TRUE(r.phi > 0 && r.phi < 1) << r.phi << "\n" << input;
    expect_all_finite(std::vector{r.gamma_tilde, r.modulus}, "gamma~ or G0", input);
    for (const auto& v : r.values)
      if (v) expect_finite(*v, "a value", input);
  }
}

TEST(FlowCurveTableFuzz, RefusesOrReadsEveryMutatedTable) {
  fuzz_text({case_file("bridge_synthetic_sweep.csv")}, 41, 1000,
            [](const std::string& text, const std::string& input) {
              return read_and_check(
                  [&] { return read_flow_curve_table(CsvTable::parse(text, "t.csv")); },
                  [&](const FlowCurveTable& table) { expect_valid(table, input); }, input);
            });
}

TEST(FlowCurveTableFuzz, RefusesOrReadsEveryMutatedPackingTable) {
  fuzz_text({case_file("bridge_synthetic_sweep_packings.csv")}, 42, 1000,
            [](const std::string& text, const std::string& input) {
              return read_and_check(
                  [&] { return read_packing_runs(CsvTable::parse(text, "p.csv")); },
                  [&](const std::vector<PackingRun>& runs) { expect_valid(runs, input); }, input);
            });
}

// The structure table of `bridge fit --structure`, merged into a table without f_m.
TEST(FlowCurveTableFuzz, RefusesOrMergesEveryMutatedStructureTable) {
  const std::string table_text =
      "phi [1],gamma_tilde [1],packings [1],sigma [E*],sigma_se [E*],G0 [E*],G0_se [E*]\n"
      "0.7,1e-6,2,1e-3,1e-5,0.03,1e-4\n0.7,1e-5,2,2e-3,1e-5,0.03,1e-4\n"
      "0.8,1e-6,2,3e-3,1e-5,0.08,1e-4\n";
  const std::string structure =
      "# structure of the runs\nphi [1],gamma_tilde [1],r_m [R],f_m [E*R^2],f_m_se [E*R^2]\n"
      "0.7,1e-6,2.01,0.015,1e-4\n0.7,1e-5,2.02,0.016,1e-4\n0.8,1e-6,1.98,0.03,2e-4\n";
  const FlowCurveTable base = read_flow_curve_table(CsvTable::parse(table_text, "t.csv"));
  fuzz_text({structure}, 43, 1000, [&](const std::string& text, const std::string& input) {
    return read_and_check(
        [&] {
          FlowCurveTable table = base;
          merge_structure(table, CsvTable::parse(text, "s.csv"));
          return table;
        },
        [&](const FlowCurveTable& table) {
          for (const StatePoint& p : table.points)
            EXPECT_TRUE(p.values[index(Quantity::force)].has_value()) << input;
          expect_valid(table, input);
        },
        input);
  });
}

}  // namespace
}  // namespace softglass::bridge
