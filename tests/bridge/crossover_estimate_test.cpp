// The crossover estimate from the flow law (bridge/law/crossover_estimate.h):
// the closed-form first harmonic of the elastic–perfectly-plastic loop
// against the loop integrated step by step (a return mapping, the way a
// plasticity code would), and the rate-dependent crossover against the
// equation it solves.
#include "bridge/law/crossover_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/errors.h"

namespace softglass::bridge {
namespace {

// The loop of an elastic–perfectly-plastic solid (G0 = σ_f = 1) strained
// x sin θ, by elastic predictor and return to ±1, over two cycles (the first
// loads from rest); the first harmonic of the second by the midpoint rule.
ElastoplasticModuli integrated_loop(double x, int steps) {
  const double dtheta = 2 * std::numbers::pi / steps;
  double sigma = 0.0, strain = 0.0, sine = 0.0, cosine = 0.0;
  for (int cycle = 0; cycle < 2; ++cycle)
    for (int k = 0; k < steps; ++k) {
      const double theta = (k + 1) * dtheta;
      const double next = x * std::sin(theta);
      sigma = std::clamp(sigma + (next - strain), -1.0, 1.0);
      strain = next;
      if (cycle == 1) {
        sine += sigma * std::sin(theta) * dtheta;
        cosine += sigma * std::cos(theta) * dtheta;
      }
    }
  return {sine / (std::numbers::pi * x), cosine / (std::numbers::pi * x)};
}

TEST(CrossoverEstimate, ElastoplasticHarmonicsAreTheLoopsIntegratedStepByStep) {
  EXPECT_EQ(elastoplastic_moduli(0.5).storage, 1.0);
  EXPECT_EQ(elastoplastic_moduli(1.0).loss, 0.0);
  // 2e5 steps a cycle: the return mapping's kink costs O(1/steps) = 3e-5.
  for (const double x : {1.01, 1.5, 2.0, 3.0, 5.0, 20.0}) {
    const ElastoplasticModuli exact = elastoplastic_moduli(x), stepped = integrated_loop(x, 200000);
    EXPECT_NEAR(exact.storage, stepped.storage, 1e-4) << x;
    EXPECT_NEAR(exact.loss, stepped.loss, 1e-4) << x;
  }
  // At x = 2 the loop is a parallelogram whose unloading ends at the bottom
  // (sin θ₁ = 0): G′ = 1/2 and G″ = 1/π exactly.
  EXPECT_NEAR(elastoplastic_moduli(2.0).storage, 0.5, 1e-14);
  EXPECT_NEAR(elastoplastic_moduli(2.0).loss, 1 / std::numbers::pi, 1e-14);
}

TEST(CrossoverEstimate, TheCrossoverRatioEqualisesTheModuli) {
  const double x = elastoplastic_crossover_ratio();
  const ElastoplasticModuli m = elastoplastic_moduli(x);
  EXPECT_NEAR(m.storage, m.loss, 1e-12);
  EXPECT_GT(elastoplastic_moduli(0.99 * x).storage, elastoplastic_moduli(0.99 * x).loss);
  EXPECT_LT(elastoplastic_moduli(1.01 * x).storage, elastoplastic_moduli(1.01 * x).loss);
}

TEST(CrossoverEstimate, TheRateRaisesTheFlowStressAtThePeakRate) {
  const double x = elastoplastic_crossover_ratio(), gamma_y = 0.035, k = 80;
  // Rate-independent limit: x* γ_y.
  EXPECT_NEAR(crossover_strain_estimate(gamma_y, k, 0.0), x * gamma_y, 1e-15);
  EXPECT_NEAR(crossover_strain_estimate(gamma_y, 0.0, 1e-6), x * gamma_y, 1e-15);
  // Otherwise γ_c = x* (γ_y + k (γ_c ω̃)^½), increasing with ω̃.
  double previous = x * gamma_y;
  for (const double omega : {1e-9, 2.31e-7, 1e-5}) {
    const double c = crossover_strain_estimate(gamma_y, k, omega);
    EXPECT_NEAR(c, x * (gamma_y + k * std::sqrt(c * omega)), 1e-12 * c) << omega;
    EXPECT_GT(c, previous);
    previous = c;
  }
  EXPECT_THROW(crossover_strain_estimate(0.0, k, 1e-7), InputError);
  EXPECT_THROW(crossover_strain_estimate(gamma_y, -1, 1e-7), InputError);
  EXPECT_THROW(crossover_strain_estimate(gamma_y, k, std::nan("")), InputError);
}

}  // namespace
}  // namespace softglass::bridge
