// The layering order parameter S_y (analysis/layering.h): its two limits.
#include <gtest/gtest.h>

#include <random>

#include "micro/analysis/layering.h"

namespace softglass::micro {
namespace {

constexpr double kSide = 17.5;

TEST(Layering, DisorderedPositionsStayFarBelowTheThreshold) {
  // Each term |Σ e^{iθ}|²/N is Exp(1) for uniform positions; the maximum of
  // M = 17 terms has mean H_17 ≈ 3.4 and exceeds 20 with probability ~ 17 e⁻²⁰.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, kSide);
  double mean = 0.0;
  for (int sample = 0; sample < 50; ++sample) {
    std::vector<Vec3> x(1000);
    for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
    const Layering l = gradient_layering(x, kSide);
    EXPECT_LT(l.order, kLayeredThreshold);
    mean += l.order / 50;
  }
  // sd of the mean of 50 maxima ≈ 1.3/√50 ≈ 0.2 (Gumbel sd π/√6 ≈ 1.3)
  EXPECT_NEAR(mean, 3.44, 0.6);
}

TEST(Layering, PerfectLayersGiveN) {
  // 11 planes y = (k + ½) L/11, each filled at random in x and z: the m = 11
  // term is |Σ 1|²/N = N exactly, also after shifting every layer by whole
  // cells (unwrapped positions).
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, kSide);
  std::vector<Vec3> x;
  for (int k = 0; k < 1100; ++k) {
    const double y = ((k % 11) + 0.5) * kSide / 11.0 + kSide * (k % 3 - 1);
    x.emplace_back(u(rng), y, u(rng));
  }
  const Layering l = gradient_layering(x, kSide);
  EXPECT_EQ(l.layers, 11);
  EXPECT_NEAR(l.order, 1100.0, 1e-8);
}

}  // namespace
}  // namespace softglass::micro
