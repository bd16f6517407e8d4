// The finite-element scenes with a tabulated law (macro/material/tabulated_law.h)
// against the 1-D quadratures of the same table (exact/couette.h,
// exact/cone_plate.h): ≤ 1e-4 relative at the accurate preset, by the
// regularised Newton solver and by ALG2; the torque's convergence order under
// refinement; and a Herschel–Bulkley law tabulated giving that law's solution.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <string>
#include <vector>

#include "fe_test_support.h"

namespace softglass::macro::testing {
namespace {

// The bound for a tabulated law against the quadrature of its table.
constexpr double kRequired = 1e-4;

// τ = τ_y + 3 γ̇^½ + 0.2 γ̇ at 11 rates over 1e-2 … 1e3 1/s: no power law, its
// local exponent rising from ½ towards 1 (tests/macro/tabulated_law_test.cpp).
std::string curved_material(double tau_y) {
  std::vector<double> rates, stresses;
  for (int i = 0; i <= 10; ++i) {
    const double r = 1e-2 * std::pow(1e5, i / 10.0);
    rates.push_back(r);
    stresses.push_back(tau_y + 3.0 * std::sqrt(r) + 0.2 * r);
  }
  return fmt::format(
      "subsection material\n set model = tabulated\n set yield stress = {}\n set rates = {:.17g}\n"
      " set stresses = {:.17g}\nend\n",
      tau_y, fmt::join(rates, ", "), fmt::join(stresses, ", "));
}

std::string couette(const std::string& solver) {
  return "set scene = couette\nsubsection couette\n set inner radius = 0.02\n set outer radius = "
         "0.03\n set length = 1\nend\nsubsection solver\n" +
         solver + "end\n";
}

// Partly yielded (slow) to fully yielded (fast) at τ_y = 4 Pa.
TEST(FeTabulated, CouetteMatchesTheQuadratureOfItsTable) {
  for (const std::string method : {"regularised", "augmented-lagrangian"}) {
    const auto rows = run_scene(
        couette(" set preset = accurate\n set method = " + method + "\n") + curved_material(4.0),
        {0.01, 0.3, 10.0});
    for (const auto& row : rows) EXPECT_LT(std::abs(row[kDeviation]), kRequired) << method;
  }
}

TEST(FeTabulated, ConePlateMatchesTheQuadratureOfItsTable) {
  const auto rows = run_scene(
      "set scene = cone-plate\nsubsection cone-plate\n set radius = 0.025\n set angle = 2\nend\n"
      "subsection solver\n set preset = accurate\nend\n" +
          curved_material(4.0),
      {0.05, 2.0});
  for (const auto& row : rows) EXPECT_LT(std::abs(row[kDeviation]), kRequired);
}

// Without a yield stress and with a tiny ε the torque's error is the
// discretisation's: an energy, so O(h^{2p}) as for Newtonian (fe_convergence_
// test.cpp), with the same allowance for the adaptive cycle (75 % of 2p).
TEST(FeTabulated, TorqueConvergesAtTwiceTheElementOrder) {
  for (const int degree : {1, 2}) {
    std::vector<double> errors;
    for (const int refinements : {1, 2, 3}) {
      const std::string solver = fmt::format(
          " set degree = {}\n set global refinements = {}\n set adaptive cycles = 1\n"
          " set relative rate scale = 1e-9\n",
          degree, refinements);
      const std::string text =
          "set scene = couette\nsubsection couette\n set inner radius = 0.02\n set outer radius "
          "= 0.03\n set length = 1\n set gap cells = 1\nend\nsubsection solver\n" +
          solver + "end\n" + curved_material(0.0);
      errors.push_back(std::abs(run_scene(text, {2.0})[0][kDeviation]));
    }
    const double order = std::log2(std::sqrt(errors[0] / errors[2]));
    EXPECT_GT(order, 0.75 * 2 * degree) << degree << ": " << fmt::format("{}", fmt::join(errors, " "));
    EXPECT_LT(errors[2], errors[1]);
  }
}

// A Herschel–Bulkley law tabulated at 7 rates is that law (tabulated_law.h):
// the FE torques of the two materials agree to the solver's own tolerance,
// inside the window and beyond it on both sides.
TEST(FeTabulated, AHerschelBulkleyTableGivesTheHerschelBulkleySolution) {
  std::vector<double> rates, stresses;
  for (int i = 0; i <= 6; ++i) {
    rates.push_back(0.1 * std::pow(10.0, i / 2.0));
    stresses.push_back(10.0 + 5.0 * std::sqrt(rates.back()));
  }
  const std::string table = fmt::format(
      "subsection material\n set model = tabulated\n set yield stress = 10\n set rates = {:.17g}\n"
      " set stresses = {:.17g}\nend\n",
      fmt::join(rates, ", "), fmt::join(stresses, ", "));
  const std::vector<double> omegas{4.23276e-3, 0.890221, 34.7549};
  const auto tabulated = run_scene(couette("") + table, omegas);
  const auto closed = run_scene(couette("") + material(10.0, 5.0, 0.5), omegas);
  for (std::size_t k = 0; k < omegas.size(); ++k)
    EXPECT_NEAR(tabulated[k][kValue] / closed[k][kValue], 1.0, 1e-8) << omegas[k];
}

}  // namespace
}  // namespace softglass::macro::testing
