// `bridge material --tabulated` (bridge/material/tabulated_material.h) on the
// bundled law of the project's paper sweep: at a simulated φ the table is the
// simulated points in SI units; between two it is their log-linear blend,
// with an interpolation error; across the range it is a flow curve macro
// accepts; and it reads back as the documented fragment.
#include <deal.II/base/parameter_handler.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "bridge/material/tabulated_material.h"
#include "bridge_test_support.h"
#include "bundled_law.h"
#include "common/csv_table.h"
#include "common/errors.h"
#include "tests/common/test_files.h"

namespace softglass::bridge {
namespace {

using Fixture = testing::BundledLaw;
const std::filesystem::path& kLawFile = testing::kBundledLaw;

// σ̃ at (φ, γ̃) straight from the points file.
double point(double phi, double gamma_tilde) {
  const CsvTable csv = CsvTable::read(std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" /
                                      "bridge_law_paper_sweep_points.csv");
  for (std::size_t r = 0; r < csv.rows(); ++r)
    if (std::abs(csv.number(r, 0) - phi) < 1e-12 &&
        std::abs(csv.number(r, 1) / gamma_tilde - 1.0) < 1e-9)
      return csv.number(r, *csv.find("sigma [E*]"));
  ADD_FAILURE() << "no point " << phi << " " << gamma_tilde;
  return 0.0;
}

TEST(TabulatedMaterial, AtASimulatedPhiTheTableIsTheSimulatedPointsInSi) {
  const Fixture f;
  const double e_star = 3000.0, eta = 2e-3;
  const TabulatedMaterial m = make_tabulated_material(f.law, f.curves, {0.8, e_star, eta, false});
  ASSERT_EQ(m.rows.size(), f.curves.gamma_tilde.size());
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    const double g = f.curves.gamma_tilde[i];
    EXPECT_NEAR(m.rows[i].rate / (g * e_star / eta), 1.0, 1e-14) << i;
    const MaterialValue& s = *m.rows[i].value[index(Quantity::sigma)];
    EXPECT_NEAR(s.value / (e_star * point(0.8, g)), 1.0, 1e-12) << i;
    EXPECT_EQ(s.interpolation, 0.0) << i;
    EXPECT_GT(s.statistical, 0.0) << i;
  }
  EXPECT_GT(m.yield.value, 0.0);
  EXPECT_LT(m.yield.value, m.rows.front().value[index(Quantity::sigma)]->value);
}

// Midway between 0.8 and 0.85 the weights are ½, ½: the geometric mean.
TEST(TabulatedMaterial, BetweenSimulatedPhiTheLogLinearBlend) {
  const Fixture f;
  const TabulatedMaterial m = make_tabulated_material(f.law, f.curves, {0.825, 1.0, 1.0, false});
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    const double g = f.curves.gamma_tilde[i];
    const MaterialValue& s = *m.rows[i].value[index(Quantity::sigma)];
    EXPECT_NEAR(s.value / std::sqrt(point(0.8, g) * point(0.85, g)), 1.0, 1e-12) << i;
    EXPECT_GT(s.interpolation, 0.0) << i;
  }
}

// Across the simulated range every table increases with the rate and starts
// above its yield stress (rows on the yield plateau left out): what macro's
// tabulated law requires.
TEST(TabulatedMaterial, EveryVolumeFractionGivesAFlowCurve) {
  const Fixture f;
  for (double phi = 0.70; phi <= 0.9001; phi += 0.01) {
    const TabulatedMaterial m = make_tabulated_material(f.law, f.curves, {phi, 1e3, 1e-3, false});
    ASSERT_GE(m.rows.size(), 2u) << phi;
    double previous = m.yield.value;
    for (const TabulatedRow& row : m.rows) {
      const double s = row.value[index(Quantity::sigma)]->value;
      EXPECT_GT(s, previous) << phi << " at " << row.rate;
      previous = s;
    }
    for (const TabulatedRow& row : m.plateau_rows)
      EXPECT_LE(row.value[index(Quantity::sigma)]->value, m.yield.value) << phi;
  }
}

TEST(TabulatedMaterial, WritesTheDocumentedFragment) {
  const Fixture f;
  const TabulatedMaterial m = make_tabulated_material(f.law, f.curves, {0.85, 3857.0, 8.9e-4, false});
  const std::string text = tabulated_material_text(m, {"softglass bridge material (test)"});
  testing::expect_contains(text, {"# softglass bridge material (test)\n", "set model        = "
                                  "tabulated", "statistical", "interpolation", "power laws"});
  dealii::ParameterHandler prm;
  namespace P = dealii::Patterns;
  prm.enter_subsection("material");
  prm.declare_entry("model", "", P::Anything());
  for (const char* name : {"yield stress", "N1 yield", "N2 yield"})
    prm.declare_entry(name, "0", P::Double());
  for (const char* name : {"rates", "stresses", "N1 values", "N2 values"})
    prm.declare_entry(name, "", P::List(P::Double()));
  prm.leave_subsection();
  prm.parse_input_from_string(text);
  prm.enter_subsection("material");
  EXPECT_EQ(prm.get("model"), "tabulated");
  const auto list = [&prm](const char* name) {
    std::vector<double> out;
    for (const auto& item : dealii::Utilities::split_string_list(prm.get(name)))
      out.push_back(dealii::Utilities::string_to_double(item));
    return out;
  };
  const std::vector<double> rates = list("rates"), stresses = list("stresses");
  ASSERT_EQ(rates.size(), m.rows.size());
  ASSERT_EQ(stresses.size(), m.rows.size());
  ASSERT_EQ(list("N1 values").size(), m.rows.size());
  for (std::size_t i = 0; i < rates.size(); ++i) {
    EXPECT_NEAR(rates[i] / m.rows[i].rate, 1.0, 1e-5);
    EXPECT_NEAR(stresses[i] / m.rows[i].value[index(Quantity::sigma)]->value, 1.0, 1e-5);
  }
  EXPECT_NEAR(prm.get_double("yield stress") / m.yield.value, 1.0, 1e-5);
  prm.leave_subsection();
}

TEST(TabulatedMaterial, WithoutTheSimulatedPointsTheLawFileIsRefused) {
  const softglass::testing::TemporaryDirectory dir;
  std::filesystem::copy_file(kLawFile, dir / "law.prm");
  const Law law = read_law_file(dir / "law.prm");
  try {
    read_simulated_curves(dir / "law.prm", law);
    ADD_FAILURE() << "accepted a law without its points";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("law_points.csv is missing"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace softglass::bridge
