// The Herschel–Bulkley fit and its least-squares machinery: exact recovery,
// covariance against Monte Carlo, goodness of fit, and the plateau check.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bridge/fit/herschel_bulkley.h"
#include "bridge/fit/least_squares.h"
#include "bridge_test_support.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

// y = law(x) at 11 rates from 1e-9 to 1e-4 with relative errors `rel`, noise drawn if rng given.
Curve curve_of(const HbParameters& law, double rel, std::mt19937_64* rng = nullptr,
               double low = 1e-9, double high = 1e-4, int n = 11) {
  Curve c;
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i) {
    const double x = low * std::pow(high / low, double(i) / (n - 1));
    const double y = law(x), se = rel * std::abs(y);
    c.x.push_back(x);
    c.y.push_back(y + (rng ? se * normal(*rng) : 0.0));
    c.se.push_back(se);
  }
  return c;
}

TEST(HerschelBulkley, RecoversExactParameters) {
  // Round-off only: the solver's tolerances are 1e-12 relative.
  for (const HbParameters truth : {HbParameters{2.5e-3, 6.8, 0.5}, HbParameters{1e-3, 0.2, 0.35},
                                   HbParameters{-1.5e-3, -1.3, 0.62}}) {
    const HerschelBulkleyFit fit = fit_herschel_bulkley(curve_of(truth, 0.01));
    ASSERT_TRUE(fit.converged) << fit.status;
    EXPECT_NEAR(fit.parameters.yield, truth.yield, 1e-8 * std::abs(truth.yield));
    EXPECT_NEAR(fit.parameters.consistency, truth.consistency, 1e-7 * std::abs(truth.consistency));
    EXPECT_NEAR(fit.parameters.exponent, truth.exponent, 1e-8);
    EXPECT_LT(fit.goodness.chi2, 1e-12);
    EXPECT_EQ(fit.goodness.dof, 8);
  }
}

// With known Gaussian errors, the Jacobian covariance is the spread of the
// estimates over repeated draws, and χ² averages its degrees of freedom.
TEST(HerschelBulkley, CovarianceMatchesTheScatterOfRepeatedFits) {
  const HbParameters truth{2.5e-3, 6.8, 0.5};
  std::mt19937_64 rng(42);
  const int draws = 400;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  double chi2 = 0.0;
  Eigen::Matrix3d covariance;
  for (int d = 0; d < draws; ++d) {
    const HerschelBulkleyFit fit = fit_herschel_bulkley(curve_of(truth, 0.02, &rng));
    ASSERT_TRUE(fit.converged);
    const Eigen::Vector3d p(fit.parameters.yield, fit.parameters.consistency,
                            fit.parameters.exponent);
    sum += p;
    sum2 += p.cwiseAbs2();
    chi2 += fit.goodness.chi2;
    covariance = fit.covariance;  // nearly the same for every draw (same errors)
  }
  const Eigen::Vector3d mean = sum / draws;
  const Eigen::Vector3d sd = (sum2 / draws - mean.cwiseAbs2()).cwiseSqrt();
  for (int i = 0; i < 3; ++i) {
    // The sample sd of 400 draws is itself uncertain by 1/√800 = 3.5 %; allow 12 %
    // (3.5 sd) for that and the fit's mild nonlinearity.
    EXPECT_NEAR(sd(i) / std::sqrt(covariance(i, i)), 1.0, 0.12) << "parameter " << i;
  }
  // χ²_8 has standard deviation 4: the mean of 400 is 8 ± 0.2; allow 4 sd.
  EXPECT_NEAR(chi2 / draws, 8.0, 0.8);
}

TEST(HerschelBulkley, NeedsFourRates) {
  Curve c = curve_of({1e-3, 1.0, 0.5}, 0.01, nullptr, 1e-8, 1e-5, 3);
  EXPECT_THROW(fit_herschel_bulkley(c), InputError);
}

TEST(HerschelBulkley, PlateauCheckRefusesCurvesWithoutYieldStress) {
  std::mt19937_64 rng(7);
  // A power-law fluid: no yield stress at all.
  const Curve fluid = curve_of({0.0, 6.8, 0.5}, 0.02, &rng);
  const PlateauCheck none = check_plateau(fluid, fit_herschel_bulkley(fluid));
  EXPECT_FALSE(none.ok);
  expect_contains(none.reason, {"not significantly different from zero"});
  // A yield stress, but the rates never come down to it: at the lowest rate
  // the power law is 9 times the yield value.
  const Curve high_rates = curve_of({1e-4, 6.8, 0.5}, 0.005, &rng, 1e-8, 1e-4);
  const PlateauCheck early = check_plateau(high_rates, fit_herschel_bulkley(high_rates));
  EXPECT_FALSE(early.ok);
  expect_contains(early.reason, {"has not reached its yield plateau"});
  const Curve good = curve_of({2.5e-3, 6.8, 0.5}, 0.02, &rng);
  EXPECT_TRUE(check_plateau(good, fit_herschel_bulkley(good)).ok);
}

TEST(HerschelBulkley, SquareRootLawIsExactForMHalf) {
  const SquareRootLaw law = fit_square_root_law(curve_of({2e-3, 7.0, 0.5}, 0.01));
  EXPECT_NEAR(law.intercept, 2e-3, 1e-14);
  EXPECT_NEAR(law.slope, 7.0, 1e-10);
}

// With errors estimated from few samples, χ²/dof follows F(dof, ν): the same
// χ² is less surprising than under χ²_dof.
TEST(GoodnessOfFit, UsesFisherFWhenTheErrorsAreEstimates) {
  const GoodnessOfFit exact = goodness_of_fit(26.1, 8);  // the χ²_8 0.1 % point
  EXPECT_NEAR(exact.p_value, 1e-3, 1e-4);
  const GoodnessOfFit estimated = goodness_of_fit(26.1, 8, 40.0);
  EXPECT_GT(estimated.p_value, 4e-3);
  EXPECT_NEAR(estimated.reduced_chi2(), 26.1 / 8, 1e-12);
  EXPECT_TRUE(std::isnan(goodness_of_fit(1.0, 0).p_value));
}

}  // namespace
}  // namespace softglass::bridge
