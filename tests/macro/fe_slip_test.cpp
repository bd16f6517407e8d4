// The finite-element scenes with wall slip against the exact solutions
// (macro/exact/couette.h, channel.h, pipe.h) at the standard preset, ≤ 1e-3
// relative like every closed form (fe_scenes_test.cpp); the meridian-plane
// scenes against closed forms of Navier slip; and the limit β → 0.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fe_test_support.h"
#include "macro_test_support.h"

namespace softglass::macro::testing {
namespace {

constexpr double kRequired = 1e-3;
constexpr double kPi = std::numbers::pi;

std::string slip_law(double beta, double p, double yield = 0.0) {
  return fmt::format(
      "subsection slip\n set law = power-law\n set coefficient = {}\n set exponent = {}\n"
      " set yield stress = {}\nend\n",
      beta, p, yield);
}

// macro.md's cell (R1 = 20 mm, R2 = 30 mm, L = 1 m) and law (τ_y = 10 Pa,
// K = 5 Pa s^½, n = ½).
std::string couette(const std::string& walls) {
  return "set scene = couette\nsubsection couette\n set inner radius = 0.02\n set outer radius = "
         "0.03\n set length = 1\n set slip walls = " +
         walls + "\nend\n" + material(10.0, 5.0, 0.5);
}

// The fixed-load law (p = 2, β = 2e-5 m/s/Pa²: slip and bulk shear of the
// same size at 1 rad/s) on the bob, the cup and both, and a slip yield stress
// on both; Ω from slip-dominated (0.01 rad/s: the gap partly or not yielded)
// to bulk-dominated.
TEST(FeCouetteSlip, MatchesTheExactTorque) {
  for (const char* walls : {"bob", "cup", "bob, cup"}) {
    for (const std::string& law : {slip_law(2e-5, 2.0), slip_law(2e-5, 2.0, 3.0)}) {
      const auto rows = run_scene(couette(walls) + law, {0.01, 1.0, 30.0});
      for (const auto& row : rows)
        EXPECT_LT(std::abs(row[kDeviation]), kRequired) << walls << " " << row[kValue];
    }
  }
}

// The plane channel (H = 10 mm), both walls slipping: τ_w = 20 Pa (HB,
// φ = 1/4, and Newtonian) and τ_w = 4 Pa < τ_y, a plug sliding whole.
TEST(FeChannelSlip, MatchesTheExactFlowRate) {
  const std::string channel =
      "set scene = channel\nsubsection channel\n set half height = 0.01\n set slip walls = "
      "walls\nend\n";
  for (const std::string& bulk : {material(5.0, 2.0, 0.5), material(0.0, 2.0, 1.0)}) {
    for (const std::string& law : {slip_law(2e-6, 2.0), slip_law(1e-5, 1.0), slip_law(1e-5, 2.0, 2.0)}) {
      const auto rows = run_scene(channel + bulk + law, {2000.0, 400.0});
      for (const auto& row : rows) EXPECT_LT(std::abs(row[kDeviation]), kRequired) << law;
    }
  }
  // The pipe alike (R = 10 mm, τ_w = 20 Pa).
  const auto pipe = run_scene(
      "set scene = pipe\nsubsection pipe\n set radius = 0.01\n set slip walls = wall\nend\n" +
          material(5.0, 2.0, 0.5) + slip_law(2e-6, 2.0),
      {4000.0});
  EXPECT_LT(std::abs(pipe[0][kDeviation]), kRequired);
}

// β → 0 is no slip: the slipping cell's torque tends to the no-slip one.
// With β = 1e-12 m/s/Pa² the true slip changes the torque by ~1e-9; the
// regularised law's linear core (slip_law.h: dσ/dV = k ε_V^{m−1} at rest)
// lets the wall slide at up to σ_w ε_V^{1/2} β^{1/2}, which changes it by
// ~1e-6 of itself at the standard preset.
TEST(FeCouetteSlip, VanishingSlipCoefficientIsNoSlip) {
  const auto slipping = run_scene(couette("bob, cup") + slip_law(1e-12, 2.0), {0.01, 1.0});
  const auto sticking = run_scene(couette(""), {0.01, 1.0});
  for (int k = 0; k < 2; ++k)
    EXPECT_LT(relative_error(slipping[k][kValue], sticking[k][kValue]), 1e-5) << k;
}

// Parallel plates, Newtonian (μ), Navier slip V = βσ on both plates: the
// torsional flow ω = Ω (z + b)/(h + 2b) with slip length b = βμ solves it
// (rim traction-free, ∂ω/∂r = 0), so T = π μ Ω R⁴ / (2 (h + 2b)). ω is linear
// in z, in the finite-element space, and every integrand a polynomial the
// quadrature integrates exactly: only Newton's tolerance and rounding remain.
TEST(FeParallelPlatesSlip, NavierSlipIsAWiderGap) {
  const double R = 0.02, h = 0.001, mu = 2.0, beta = 2e-4, omega = 3.0;
  const auto rows = run_scene(
      "set scene = parallel-plates\nsubsection parallel-plates\n set radius = 0.02\n set gap = "
      "0.001\n set slip walls = upper plate, lower plate\nend\n" +
          material(0.0, mu, 1.0) + slip_law(beta, 1.0),
      {omega});
  const double b = beta * mu;
  EXPECT_LT(relative_error(rows[0][kValue], kPi * mu * omega * R * R * R * R / (2.0 * (h + 2.0 * b))),
            1e-9);
}

// Cone and plate, Newtonian, Navier slip on cone and plate: in the
// lubrication limit each ring r is a plane gap r tan β widened by the two slip
// lengths, γ̇ = Ω r/(r tan β + 2b), T = 2π μ Ω ∫₀^R r³/(r tan β + 2b) dr. At
// β = 2° the finite angle changes the no-slip torque by 6e-4 (0.999391,
// macro.md); the slip lengths here (2b = R tan β/2, half the rim's gap) are of the gap's
// size, so the lubrication value holds to that order: 2e-3.
TEST(FeConePlateSlip, NavierSlipMatchesLubrication) {
  const double R = 0.025, angle = 2.0 * kPi / 180.0, mu = 2.0, omega = 1.0;
  const double b = 0.25 * R * std::tan(angle), beta = b / mu;
  const auto rows = run_scene(
      "set scene = cone-plate\nsubsection cone-plate\n set radius = 0.025\n set angle = 2\n"
      " set truncation = 1e-9\n set slip walls = cone, plate\nend\n" +
          material(0.0, mu, 1.0) + slip_law(beta, 1.0),
      {omega});
  const double lubrication =
      2.0 * kPi * mu * omega *
      gauss_kronrod([&](double r) { return r * r * r / (r * std::tan(angle) + 2.0 * b); }, 0.0, R);
  EXPECT_LT(relative_error(rows[0][kValue], lubrication), 2e-3);
}

}  // namespace
}  // namespace softglass::macro::testing
