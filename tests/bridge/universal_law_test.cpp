// The universal fits over all volume fractions, on exact synthetic curves.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

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

// The universal law of quantity q fitted over every φ of the truth.
UniversalFit fit_exact(const testing::SyntheticTruth& t, Quantity q, double sign) {
  std::vector<Curve> curves;
  for (std::size_t j = 0; j < t.phi.size(); ++j) curves.push_back(exact_curve(t, j, q));
  std::vector<const Curve*> pointers;
  for (const Curve& c : curves) pointers.push_back(&c);
  return fit_universal_law(pointers, t.modulus, sign);
}

TEST(UniversalLaw, RecoversKAndTheYieldStressesExactly) {
  const testing::SyntheticTruth t;
  const UniversalFit fit = fit_exact(t, Quantity::sigma, 1.0);
  ASSERT_TRUE(fit.converged) << fit.status;
  EXPECT_NEAR(fit.k, t.k, 1e-8 * t.k);
  for (std::size_t j = 0; j < t.phi.size(); ++j)
    EXPECT_NEAR(fit.yield[j], t.sigma_yield(j), 1e-10 * t.sigma_yield(j));
  EXPECT_LT(fit.goodness.chi2, 1e-12);
}

TEST(UniversalLaw, RecoversTheNormalStressConstantsWithTheirSigns) {
  const testing::SyntheticTruth t;
  // N2 falls with the rate: its law has the sign −1 and a positive k″.
  for (const auto& [q, k, sign] :
       {std::tuple(Quantity::N1, t.k_N1, 1.0), std::tuple(Quantity::N2, t.k_N2, -1.0)}) {
    const UniversalFit fit = fit_exact(t, q, sign);
    ASSERT_TRUE(fit.converged) << fit.status;
    EXPECT_NEAR(fit.k, k, 1e-8 * k);
    for (std::size_t j = 0; j < t.phi.size(); ++j)
      EXPECT_NEAR(fit.yield[j], t.normal_yield(j, q), 1e-10 * std::abs(t.normal_yield(j, q)));
  }
}

// The plateaus scale out of the rate term: k′ stays defined when the
// simulations cannot tell N1_y from zero (the law N/N_y = 1 + k′ … could not).
TEST(UniversalLaw, RecoversKPrimeWhenThePlateausVanish) {
  testing::SyntheticTruth t;
  t.N1_ratio = 0.0;
  const UniversalFit fit = fit_exact(t, Quantity::N1, 1.0);
  ASSERT_TRUE(fit.converged) << fit.status;
  EXPECT_NEAR(fit.k, t.k_N1, 1e-8 * t.k_N1);
  for (std::size_t j = 0; j < t.phi.size(); ++j)
    EXPECT_NEAR(fit.yield[j], 0.0, 1e-10 * t.sigma_yield(j));
}

TEST(UniversalLaw, CollapseRateIsGammaTildeOverYieldStrainSquared) {
  EXPECT_DOUBLE_EQ(collapse_rate(1e-6, 0.02), 1e-6 / 4e-4);
}

}  // namespace
}  // namespace softglass::bridge
