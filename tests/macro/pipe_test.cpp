// Pipe (macro/exact/pipe.h): the closed-form flow rate against direct
// integration of the velocity profile, the profile against the flow curve,
// Buckingham–Reiner, the power law and Hagen–Poiseuille.
#include "macro/exact/pipe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "macro_test_support.h"

namespace softglass::macro::exact {
namespace {

using testing::gauss_kronrod;
using testing::relative_error;

const Pipe kPipe{.radius = 0.01, .pressure_gradient = 4000.0};  // τ_w = 20 Pa

std::vector<HerschelBulkley> laws() {
  std::vector<HerschelBulkley> result;
  for (double tau_y : {0.0, 2.0, 10.0, 19.0})
    for (double n : {0.3, 0.5, 1.0, 1.6}) result.push_back({tau_y, 5.0, n});
  return result;
}

// Q = 2π∫₀^R w r dr, split at the plug radius (a kink of w).
TEST(Pipe, FlowRateIsTheIntegralOfTheProfile) {
  for (const HerschelBulkley& law : laws()) {
    const double r0 = plug_radius(law, kPipe), R = kPipe.radius;
    const auto wr = [&](double r) { return velocity(law, kPipe, r) * r; };
    const double integral = 2.0 * std::numbers::pi * (gauss_kronrod(wr, 0.0, r0) + gauss_kronrod(wr, r0, R));
    EXPECT_LT(relative_error(flow_rate(law, kPipe), integral), 1e-12)
        << law.yield_stress << " " << law.flow_index;
  }
}

// w(r) = ∫_r^R γ̇(G s/2) ds.
TEST(Pipe, ProfileIntegratesTheFlowCurve) {
  const double G = kPipe.pressure_gradient, R = kPipe.radius;
  for (const HerschelBulkley& law : laws()) {
    const double r0 = plug_radius(law, kPipe);
    for (double r : {0.0, 0.002, 0.005, 0.0095}) {
      const double reference =
          gauss_kronrod([&](double s) { return law.rate(0.5 * G * s); }, std::max(r, r0), R);
      EXPECT_LT(relative_error(velocity(law, kPipe, r), reference), 1e-12)
          << law.yield_stress << " " << law.flow_index << " " << r;
    }
    EXPECT_EQ(velocity(law, kPipe, R), 0.0);
  }
}

TEST(Pipe, PlugAndNoFlow) {
  EXPECT_DOUBLE_EQ(plug_radius(bingham(10.0, 1.0), kPipe), 0.005);
  EXPECT_EQ(flow_rate(bingham(20.0, 1.0), kPipe), 0.0);
  EXPECT_EQ(velocity(bingham(25.0, 1.0), kPipe, 0.0), 0.0);
}

TEST(Pipe, BuckinghamReinerPowerLawAndHagenPoiseuille) {
  const double G = kPipe.pressure_gradient, R = kPipe.radius, tau_w = G * R / 2.0, mu = 0.8;
  const double hagen_poiseuille = std::numbers::pi * std::pow(R, 4) * G / (8.0 * mu);
  EXPECT_LT(relative_error(flow_rate(newtonian(mu), kPipe), hagen_poiseuille), 1e-14);
  EXPECT_LT(relative_error(velocity(newtonian(mu), kPipe, 0.004), G * (R * R - 0.004 * 0.004) / (4.0 * mu)),
            1e-14);
  // Buckingham–Reiner: Q = (πR⁴G/8μ)(1 − 4φ/3 + φ⁴/3).
  for (double phi : {0.1, 0.5, 0.9}) {
    const double expected = hagen_poiseuille * (1.0 - 4.0 * phi / 3.0 + std::pow(phi, 4) / 3.0);
    EXPECT_LT(relative_error(flow_rate(bingham(phi * tau_w, mu), kPipe), expected), 1e-12) << phi;
  }
  // Power law: Q = πR³ (τ_w/K)^{1/n} n/(3n+1).
  for (double n : {0.3, 0.5, 1.7}) {
    const double expected = std::numbers::pi * R * R * R * std::pow(tau_w / 5.0, 1.0 / n) * n / (3.0 * n + 1.0);
    EXPECT_LT(relative_error(flow_rate(power_law(5.0, n), kPipe), expected), 1e-13) << n;
  }
}

TEST(Pipe, VanishingYieldStressGivesThePowerLaw) {
  const double power = flow_rate(power_law(5.0, 0.5), kPipe);
  for (double tau_y : {1e-3, 1e-6, 1e-9}) {
    EXPECT_LT(relative_error(flow_rate(HerschelBulkley{tau_y, 5.0, 0.5}, kPipe), power),
              10.0 * tau_y / wall_stress(kPipe))
        << tau_y;
  }
}

}  // namespace
}  // namespace softglass::macro::exact
