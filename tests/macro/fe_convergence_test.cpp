// Convergence of the finite-element solutions: the discretisation error under
// uniform refinement at the order the elements promise, and the
// regularisation error following the O(ε) law of macro.md — with the solver's
// own error estimates of the right size.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fe_test_support.h"

namespace softglass::macro::testing {
namespace {

// Newtonian Couette cell (ω(r) = A/r² + B, not a polynomial): torque
// T = 4πμLΩ R1²R2²/(R2² − R1²) without slip; with Navier slip V = βσ on both
// cylinders the slip layers add in series (exact/couette.h),
// T = Ω / [(1/R1² − 1/R2²)/(4πμL) + β/(2πL R1³) + β/(2πL R2³)].
// The torque is an energy (T Ω = ∫ τγ̇ + ∫ σ_w V_s), so it converges at twice
// the order of the gradient: h² for Q1 and h⁴ for Q2, slip or not.
// `adaptive cycles = 1` with `refine fraction` = all cells is one uniform
// refinement; meshes of 2, 4, 8 (Q1) or 1, 2, 4 (Q2) cells before it.
double newtonian_couette_error(int degree, int refinements, double beta) {
  const double R1 = 0.02, R2 = 0.03, mu = 3.0, omega = 2.0, L = 1.0;
  const std::string slip =
      beta > 0.0 ? fmt::format(" set slip walls = bob, cup\nend\nsubsection slip\n set law = "
                               "power-law\n set coefficient = {}\n set exponent = 1\n",
                               beta)
                 : "";
  const std::string text =
      "set scene = couette\nsubsection couette\n set inner radius = 0.02\n set outer radius = "
      "0.03\n"
      " set length = 1\n set gap cells = 1\n" + slip + "end\nsubsection solver\n set degree = " +
      std::to_string(degree) + "\n set global refinements = " + std::to_string(refinements) +
      "\n set adaptive cycles = 1\nend\n" + material(0.0, mu, 1.0);
  const double compliance = (1.0 / (R1 * R1) - 1.0 / (R2 * R2)) / (4.0 * std::numbers::pi * mu * L) +
                            beta / (2.0 * std::numbers::pi * L) * (1.0 / (R1 * R1 * R1) + 1.0 / (R2 * R2 * R2));
  return std::abs(run_scene(text, {omega})[0][kValue] * compliance / omega - 1.0);
}

// β = 5e-4 m/s/Pa: slip lengths βμ = 1.5 mm (the gap is 10 mm), the slip
// layers a quarter of the compliance.
TEST(FeConvergence, TorqueConvergesAtTwiceTheElementOrder) {
  for (const double beta : {0.0, 5e-4}) {
    for (int degree : {1, 2}) {
      const double e0 = newtonian_couette_error(degree, 1, beta),
                   e1 = newtonian_couette_error(degree, 2, beta),
                   e2 = newtonian_couette_error(degree, 3, beta);
      // The adaptive cycle refines a fixed fraction (30 %), not every cell, so
      // each step is less than a halving of h everywhere: require 75 % of the
      // nominal order 2p.
      const double order = std::log2(std::sqrt(e0 / e2));
      EXPECT_GT(order, 0.75 * 2 * degree)
          << beta << " " << degree << ": " << e0 << " " << e1 << " " << e2;
      EXPECT_LT(e2, e1);
    }
  }
}

// Herschel–Bulkley channel, φ = 0.25, n = 1/2, on the accurate mesh (its
// discretisation error ~1e-7 is far below the regularisation error here).
struct Regularised {
  double error, estimate;
};
Regularised channel_with(const std::string& regularisation, double relative_rate_scale) {
  const std::string text =
      "set scene = channel\nsubsection channel\n set half height = 0.01\nend\n"
      "subsection solver\n set preset = accurate\n set regularisation = " +
      regularisation + "\n set relative rate scale = " + std::to_string(relative_rate_scale) +
      "\nend\n" + material(5.0, 2.0, 0.5);
  const auto row = run_scene(text, {2000.0})[0];
  return {std::abs(row[kDeviation]), row[kRegularisation] / row[kValue]};
}

TEST(FeConvergence, RegularisationErrorIsFirstOrderInEpsilon) {
  for (const char* name : {"papanastasiou", "bercovier-engelman"}) {
    const Regularised coarse = channel_with(name, 1e-2), fine = channel_with(name, 1e-3);
    // O(ε): a tenfold smaller ε, a tenfold smaller error (5..20 allows for
    // the next order).
    EXPECT_GT(coarse.error / fine.error, 5.0) << name << " " << coarse.error << " " << fine.error;
    EXPECT_LT(coarse.error / fine.error, 20.0) << name;
    // The reported estimate (difference to 10ε over 9) is the error to within
    // a factor 2 below and 3 above: at ε/γ̇_c = 1e-2 the next order makes the
    // difference to 10ε grow faster than linearly, and the estimate errs on
    // the safe side (measured: 2.1 times the error for Papanastasiou).
    for (const Regularised& r : {coarse, fine}) {
      EXPECT_GT(r.estimate, 0.5 * r.error) << name;
      EXPECT_LT(r.estimate, 3.0 * r.error) << name;
    }
  }
}

}  // namespace
}  // namespace softglass::macro::testing
