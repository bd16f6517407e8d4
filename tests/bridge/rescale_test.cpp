// `bridge rescale` on curves made from the universal law with known τ_y, γ_y
// and E*: what is fitted comes back within its error, the rescaled points lie
// on 1 + k √x, and inconsistent settings are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "bridge/rescale/law_yield_strain.h"
#include "bridge/rescale/rescale.h"
#include "bridge_test_support.h"
#include "common/errors.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

// τ = τ_y (1 + k √(γ̇ η_s/(E* γ_y²))), N1 = N1_y + k′ τ_y √(…), 1e-3 … 1e3 1/s,
// with 2 % relative noise.
struct Sample {
  double tau_y = 100.0, gamma_y = 0.03, modulus = 40e3, viscosity = 1e-3, n1_yield = 40.0;
};
MeasuredCurve measured(const Sample& s, std::uint64_t seed, double noise = 0.02) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  MeasuredCurve c;
  c.label = "sample";
  c.N1.emplace();
  for (int i = 0; i <= 24; ++i) {
    const double rate = std::pow(10.0, -3 + 0.25 * i);
    const double root = std::sqrt(rate * s.viscosity / s.modulus) / s.gamma_y;
    c.shear_rate.push_back(rate);
    c.stress.push_back(s.tau_y * (1 + 80 * root) * (1 + noise * normal(rng)));
    c.N1->push_back((s.n1_yield + 20 * s.tau_y * root) * (1 + noise * normal(rng)));
  }
  return c;
}

RescaleSettings settings_for(const Sample& s) {
  RescaleSettings r;
  r.viscosity = s.viscosity;
  r.yield_strain = {s.gamma_y};
  return r;
}

// Within 4 standard errors (a handful of parameters per test: a false alarm rate
// below 1e-3); the fits' errors themselves are Jacobian errors, accurate here
// since the noise is Gaussian and the model right.
void expect_within(const Estimate& e, double truth, const char* what) {
  EXPECT_LT(std::abs(e.value - truth), 4 * e.error) << what << ": " << e.value << " ± " << e.error;
  EXPECT_GT(e.error, 0.0) << what;
}

TEST(Rescale, FitsTheModulusWhenItIsUnknown) {
  const Sample s;
  const auto out = rescale({measured(s, 1)}, settings_for(s));
  ASSERT_EQ(out.size(), 1u);
  const RescaledCurve& r = out[0];
  EXPECT_TRUE(r.modulus_fitted && r.yield_stress_fitted);
  expect_within(r.modulus, s.modulus, "E*");
  expect_within(r.yield_stress, s.tau_y, "tau_y");
  expect_within(*r.N1_yield, s.n1_yield, "N1_y");
  EXPECT_NEAR(r.rms_residual, 0.02, 0.006) << "the residuals are the 2 % noise";
  for (std::size_t i = 0; i < r.collapse_rate.size(); ++i)
    EXPECT_NEAR(r.stress_ratio[i] / (1 + 80 * std::sqrt(r.collapse_rate[i])), 1.0, 0.1);
}

// N1_y may be negative, N1 then crossing zero at low rates: the plateau is fitted
// over every point of the window, and the residuals (in units of τ_y) stay finite.
TEST(Rescale, FitsAnN1PlateauOfEitherSign) {
  Sample s;
  s.n1_yield = -30.0;
  const auto out = rescale({measured(s, 3)}, settings_for(s));
  ASSERT_EQ(out.size(), 1u);
  const RescaledCurve& r = out[0];
  ASSERT_TRUE(r.N1_yield.has_value());
  expect_within(*r.N1_yield, s.n1_yield, "N1_y");
  ASSERT_TRUE(r.N1_rms_residual.has_value());
  // 2 % noise on |N1| ≤ 330 Pa against τ_y = 100 Pa: at most 0.066 per point.
  EXPECT_LT(*r.N1_rms_residual, 0.066);
  for (double residual : *r.N1_residual) EXPECT_TRUE(std::isfinite(residual));
}

TEST(Rescale, FitsOnlyTheYieldStressWhenTheModulusIsGiven) {
  const Sample s;
  RescaleSettings settings = settings_for(s);
  settings.modulus = s.modulus;
  const RescaledCurve r = rescale({measured(s, 2)}, settings)[0];
  EXPECT_FALSE(r.modulus_fitted);
  EXPECT_EQ(r.modulus.value, s.modulus);
  EXPECT_EQ(r.modulus.error, 0.0);
  expect_within(r.yield_stress, s.tau_y, "tau_y");
  // Nothing left to fit: the points are rescaled as given.
  settings.yield_stress = {s.tau_y};
  const RescaledCurve given = rescale({measured(s, 2)}, settings)[0];
  EXPECT_FALSE(given.yield_stress_fitted);
  EXPECT_EQ(given.yield_stress.value, s.tau_y);
  EXPECT_NEAR(given.rms_residual, 0.02, 0.006);
}

// The paper's route: γ_y = τ_y/G0 with G0 measured.
TEST(Rescale, TakesTheYieldStrainFromTheShearModulus) {
  const Sample s;
  RescaleSettings settings = settings_for(s);
  settings.yield_strain.clear();
  settings.shear_modulus = {s.tau_y / s.gamma_y};
  const RescaledCurve r = rescale({measured(s, 3)}, settings)[0];
  expect_within(r.modulus, s.modulus, "E*");
  expect_within(r.yield_strain, s.gamma_y, "gamma_y");
}

TEST(Rescale, HerschelBulkleyFitOfTheMeasuredCurve) {
  const Sample s;
  const RescaledCurve r = rescale({measured(s, 4, 0.01)}, settings_for(s))[0];
  ASSERT_TRUE(r.herschel_bulkley.converged);
  // The universal law is Herschel-Bulkley with n = ½ and K = τ_y k √(η_s/E*)/γ_y.
  EXPECT_NEAR(r.herschel_bulkley.parameters.exponent, 0.5,
              4 * std::sqrt(r.herschel_bulkley.covariance(2, 2)));
  EXPECT_NEAR(r.herschel_bulkley.parameters.yield, s.tau_y,
              4 * std::sqrt(r.herschel_bulkley.covariance(0, 0)));
}

TEST(Rescale, OnlyTheRateWindowIsFitted) {
  const Sample s;
  MeasuredCurve c = measured(s, 5);
  for (std::size_t i = 0; i < 6; ++i) c.stress[i] *= 0.3;  // "wall slip" below 0.03 1/s
  RescaleSettings settings = settings_for(s);
  settings.min_rate = 0.03;
  const RescaledCurve r = rescale({c}, settings)[0];
  EXPECT_FALSE(r.used[0]);
  EXPECT_TRUE(r.used.back());
  expect_within(r.modulus, s.modulus, "E*");
  EXPECT_LT(r.rms_residual, 0.03);
}

TEST(Rescale, RefusesInconsistentSettingsAndCurvesWithoutPlateau) {
  const Sample s;
  const MeasuredCurve c = measured(s, 6);
  const auto refusal = [&](const RescaleSettings& settings, const MeasuredCurve& curve) {
    try {
      rescale({curve, curve}, settings);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << "accepted";
    return std::string();
  };
  RescaleSettings both = settings_for(s);
  both.shear_modulus = {3000};
  expect_contains(refusal(both, c), {"one of the two"});
  RescaleSettings three = settings_for(s);
  three.yield_strain = {0.03, 0.03, 0.03};
  expect_contains(refusal(three, c), {"--yield-strain", "3 values for 2 curves"});
  RescaleSettings window = settings_for(s);
  window.min_rate = 500;
  expect_contains(refusal(window, c), {"point(s) in the rate window"});
  MeasuredCurve fluid = c;  // a power-law fluid
  for (std::size_t i = 0; i < fluid.stress.size(); ++i)
    fluid.stress[i] = 50 * std::sqrt(fluid.shear_rate[i]);
  expect_contains(refusal(settings_for(s), fluid), {"yield", "--yield-stress"});
  // A given yield stress the curve never rises above leaves E* undetermined.
  RescaleSettings above = settings_for(s);
  above.yield_stress = {1e4};
  expect_contains(refusal(above, c), {"yield stress 10000 Pa is not below the measured stresses",
                                      "0 of 25 points"});
}

// A yield stress given above most of the flowing branch drives E* to where its
// error is larger than itself: refused as not determined, never printed.
TEST(Rescale, RefusesAModulusTheCurveDoesNotDetermine) {
  const Sample s;
  RescaleSettings settings = settings_for(s);
  const MeasuredCurve c = measured(s, 7);
  std::vector<double> sorted = c.stress;
  std::sort(sorted.begin(), sorted.end());
  settings.yield_stress = {sorted[sorted.size() - 4]};  // three points above it
  try {
    const auto out = rescale({c}, settings);
    ADD_FAILURE() << "E* = " << out[0].modulus.value << " +- " << out[0].modulus.error;
  } catch (const NumericalError& e) {
    expect_contains(e.what(), {"curve 'sample'", "the curve does not determine them"});
  }
}

// k′ enters only the N1 data: a law without a usable k′ still rescales curves
// without N1, and is refused for curves with N1.
TEST(Rescale, NeedsAPositiveKPrimeOnlyForNormalStressData) {
  const Sample s;
  MeasuredCurve stress_only = measured(s, 8);
  stress_only.N1.reset();
  RescaleSettings settings = settings_for(s);
  settings.k_N1 = -5.0;
  const auto out = rescale({stress_only}, settings);
  ASSERT_EQ(out.size(), 1u);
  expect_within(out[0].modulus, s.modulus, "E*");
  try {
    rescale({measured(s, 8)}, settings);
    ADD_FAILURE() << "a negative k' accepted for N1 data";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"k' = -5", "N1"});
  }
  settings.k_N1 = 20.0;
  settings.k = 0.0;
  EXPECT_THROW(rescale({stress_only}, settings), InputError);
}

// One E* for three curves of the same particles (τ_y and γ_y differ): it comes
// back within its error, that error is the scatter of the estimate over
// repeated draws, and it is smaller than the curves' own E* errors.
TEST(Rescale, FitsOneModulusSharedByAllCurves) {
  const Sample samples[] = {{50.0, 0.04}, {100.0, 0.03}, {200.0, 0.02}};
  RescaleSettings settings = settings_for(samples[0]);
  settings.yield_strain = {0.04, 0.03, 0.02};
  settings.shared_modulus = true;
  const int draws = 200;
  double sum = 0.0, sum2 = 0.0, reported = 0.0;
  for (int d = 0; d < draws; ++d) {
    const std::vector<MeasuredCurve> curves = {measured(samples[0], 100 + 3 * d),
                                               measured(samples[1], 101 + 3 * d),
                                               measured(samples[2], 102 + 3 * d)};
    const auto out = rescale(curves, settings);
    ASSERT_TRUE(out[0].modulus_shared);
    EXPECT_EQ(out[1].modulus.value, out[0].modulus.value);
    sum += out[0].modulus.value;
    sum2 += out[0].modulus.value * out[0].modulus.value;
    reported += out[0].modulus.error;
    if (d == 0) {
      expect_within(out[0].modulus, samples[0].modulus, "shared E*");
      for (std::size_t j = 0; j < 3; ++j)
        expect_within(out[j].yield_stress, samples[j].tau_y, "tau_y");
      RescaleSettings own = settings;
      own.shared_modulus = false;
      for (const RescaledCurve& r : rescale(curves, own))
        EXPECT_LT(out[0].modulus.error, r.modulus.error);
    }
  }
  const double mean = sum / draws,
               sd = std::sqrt((sum2 / draws - mean * mean) * draws / (draws - 1));
  std::printf(
      "shared E* over %d draws: mean %.0f Pa, scatter %.0f Pa, mean reported error %.0f Pa\n",
      draws, mean, sd, reported / draws);
  // 200 draws: the mean is known to sd/√200 ≈ 0.07 sd, the sd itself to 5 %.
  EXPECT_NEAR(mean, samples[0].modulus, 4 * sd / std::sqrt(draws));
  EXPECT_NEAR(reported / draws / sd, 1.0, 0.2)
      << "reported " << reported / draws << ", scatter " << sd;
  settings.modulus = 40e3;
  EXPECT_THROW(rescale({measured(samples[0], 1), measured(samples[1], 2)}, settings), InputError);
}

// Yield strains from a law: exact at simulated φ, interpolated between them,
// refused outside the range unless extrapolation is asked for; φ from labels.
TEST(Rescale, TakesTheYieldStrainsFromALaw) {
  const testing::SyntheticTruth t;
  const Law law = testing::exact_law(t);
  const std::vector<double> at_simulated = law_yield_strains(law, {0.75, 0.9}, false, "law.prm");
  EXPECT_DOUBLE_EQ(at_simulated[0], t.yield_strain[1]);
  EXPECT_DOUBLE_EQ(at_simulated[1], t.yield_strain[4]);
  // Linear between 0.75 (0.034) and 0.80 (0.029).
  EXPECT_NEAR(law_yield_strains(law, {0.78}, false, "law.prm")[0], 0.031, 1e-12);
  try {
    law_yield_strains(law, {0.68}, false, "law.prm");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"phi = 0.68", "0.7 ... 0.9", "law.prm", "--extrapolate"});
  }
  EXPECT_NEAR(law_yield_strains(law, {0.68}, true, "law.prm")[0], 0.0424, 1e-12);
  EXPECT_EQ(phi_from_labels({"0.68", "0.7"}), (std::vector<double>{0.68, 0.7}));
  EXPECT_THROW(phi_from_labels({"T_20"}), InputError);
}

}  // namespace
}  // namespace softglass::bridge
