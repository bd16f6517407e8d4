// The universal fits over all volume fractions, on exact synthetic curves.
#include <gtest/gtest.h>

#include <cmath>

#include "bridge/fit/universal_law.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

Curve exact_curve(const testing::SyntheticTruth& t, std::size_t j, Quantity q) {
  Curve c;
  for (double g : t.gamma_tilde) {
    c.x.push_back(g);
    c.y.push_back(t.value(j, q, g));
    c.se.push_back(0.02 * std::abs(c.y.back()));
  }
  return c;
}

TEST(UniversalLaw, RecoversKAndTheYieldStressesExactly) {
  const testing::SyntheticTruth t;
  std::vector<Curve> curves;
  for (std::size_t j = 0; j < t.phi.size(); ++j)
    curves.push_back(exact_curve(t, j, Quantity::sigma));
  std::vector<const Curve*> pointers;
  for (const Curve& c : curves) pointers.push_back(&c);
  const UniversalFit fit = fit_universal_stress(pointers, t.modulus);
  ASSERT_TRUE(fit.converged) << fit.status;
  EXPECT_NEAR(fit.k, t.k, 1e-8 * t.k);
  for (std::size_t j = 0; j < t.phi.size(); ++j)
    EXPECT_NEAR(fit.yield[j], t.sigma_yield(j), 1e-10 * t.sigma_yield(j));
  EXPECT_LT(fit.goodness.chi2, 1e-12);
}

TEST(UniversalLaw, RecoversTheNormalStressConstantsWithTheirSigns) {
  const testing::SyntheticTruth t;
  for (const auto& [q, k] : {std::pair(Quantity::N1, t.k_N1), std::pair(Quantity::N2, t.k_N2)}) {
    std::vector<Curve> curves;
    for (std::size_t j = 0; j < t.phi.size(); ++j) curves.push_back(exact_curve(t, j, q));
    std::vector<const Curve*> pointers;
    for (const Curve& c : curves) pointers.push_back(&c);
    const UniversalFit fit = fit_universal_normal(pointers, t.yield_strain);
    ASSERT_TRUE(fit.converged) << fit.status;
    EXPECT_NEAR(fit.k, k, 1e-8 * k);
    for (std::size_t j = 0; j < t.phi.size(); ++j)
      EXPECT_NEAR(fit.yield[j], t.normal_yield(j, q), 1e-10 * std::abs(t.normal_yield(j, q)));
  }
}

TEST(UniversalLaw, CollapseRateIsGammaTildeOverYieldStrainSquared) {
  EXPECT_DOUBLE_EQ(collapse_rate(1e-6, 0.02), 1e-6 / 4e-4);
}

}  // namespace
}  // namespace softglass::bridge
