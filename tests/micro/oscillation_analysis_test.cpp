// The harmonic analysis of oscillatory shear (micro/analysis/oscillation.h) on
// signals whose harmonics are known exactly: discrete Fourier sums recover
// them to rounding, the moduli and Chebyshev coefficients follow their
// definitions (Ewoldt et al. 2008), and the periodic state is told from a
// transient and from a drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "micro/analysis/oscillation.h"

namespace softglass::micro {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sampled(int n, const std::function<double(double)>& f) {
  std::vector<double> s;
  for (int k = 0; k < n; ++k) s.push_back(f(2.0 * kPi * k / n));
  return s;
}

std::size_t index_of(const std::string& name) {
  const auto& names = oscillation_observable_names();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

// A signal made of harmonics 0 … 5 is recovered to rounding from 16 samples
// and more (the trapezoidal rule is exact for harmonics below N/2).
TEST(FourierSeries, RecoversEveryHarmonicBelowHalfTheSamples) {
  const std::vector<double> a = {0.0, 1.5, -0.3, 0.25, 0.1, -0.05};
  const std::vector<double> b = {0.0, 0.7, 0.2, -0.4, 0.0, 0.03};
  for (int n : {16, 64, 256}) {
    const auto s = sampled(n, [&](double t) {
      double v = 0.8;
      for (int h = 1; h <= 5; ++h) v += a[h] * std::sin(h * t) + b[h] * std::cos(h * t);
      return v;
    });
    const FourierSeries f = fourier_series(s, 5);
    EXPECT_NEAR(f.mean, 0.8, 1e-14) << n;
    for (int h = 1; h <= 5; ++h) {
      EXPECT_NEAR(f.sine[h], a[h], 1e-13) << n << " harmonic " << h;
      EXPECT_NEAR(f.cosine[h], b[h], 1e-13) << n << " harmonic " << h;
    }
  }
  EXPECT_THROW(fourier_series(sampled(10, [](double t) { return t; }), 5), std::invalid_argument);
}

// A linear viscoelastic response σ = γ0 (G′ sin θ + G″ cos θ): the moduli, no
// higher harmonics, e1 = G′, v1 = G″/ω̃, e3 = v3 = 0.
TEST(CycleResponse, LinearViscoelasticSignal) {
  const double gamma0 = 1e-3, omega = 2e-7, g1 = 0.04, g2 = 0.003;
  const auto sigma = sampled(64, [&](double t) { return gamma0 * (g1 * std::sin(t) + g2 * std::cos(t)); });
  const auto elastic = sampled(64, [&](double t) { return gamma0 * g1 * std::sin(t); });
  const auto viscous = sampled(64, [&](double t) { return gamma0 * g2 * std::cos(t); });
  const std::vector<double> zero(64, 0.0), n1(64, 2e-5), pressure(64, 0.01);
  const auto r = cycle_response({sigma, elastic, viscous, viscous, n1, zero, pressure}, gamma0, omega);
  EXPECT_NEAR(r[index_of("storage")], g1, 1e-14);
  EXPECT_NEAR(r[index_of("loss")], g2, 1e-14);
  EXPECT_NEAR(r[index_of("storage_elastic")], g1, 1e-14);
  EXPECT_NEAR(r[index_of("loss_elastic")], 0.0, 1e-14);
  EXPECT_NEAR(r[index_of("loss_viscous")], g2, 1e-14);
  EXPECT_NEAR(r[index_of("loss_film")], g2, 1e-14);
  EXPECT_NEAR(r[index_of("intensity_3")], 0.0, 1e-12);
  EXPECT_NEAR(r[index_of("e1")], g1, 1e-14);
  EXPECT_NEAR(r[index_of("e3")], 0.0, 1e-12);
  EXPECT_NEAR(r[index_of("v1")], g2 / omega, 1e-14 / omega);
  EXPECT_NEAR(r[index_of("v3")], 0.0, 1e-12 / omega);
  EXPECT_NEAR(r[index_of("N1")], 2e-5, 1e-18);
  EXPECT_NEAR(r[index_of("pressure")], 0.01, 1e-16);
}

// The Chebyshev coefficients rebuild the elastic stress as a function of the
// strain, σ′(x) = γ0 (e1 T1(x) + e3 T3(x)), x = γ/γ0, and the viscous one of
// the rate, σ″(y) = γ̇0 (v1 T1(y) + v3 T3(y)), y = γ̇/γ̇0 (ω̃ = γ̇0/γ0 in reduced
// units): a third-harmonic signal is rebuilt point by point, which fixes the
// signs (e3 > 0 stiffening, v3 < 0 thinning).
TEST(CycleResponse, ChebyshevCoefficientsRebuildTheElasticAndViscousStresses) {
  const double gamma0 = 0.3, omega = 1e-6;
  const double g1 = 0.02, g3 = -0.004, h1 = 0.006, h3 = -0.0015;
  const auto elastic = [&](double t) { return gamma0 * (g1 * std::sin(t) + g3 * std::sin(3 * t)); };
  const auto viscous = [&](double t) { return gamma0 * (h1 * std::cos(t) + h3 * std::cos(3 * t)); };
  const auto sigma = sampled(128, [&](double t) { return elastic(t) + viscous(t); });
  const std::vector<double> zero(128, 0.0);
  const auto r = cycle_response({sigma, zero, zero, zero, zero, zero, zero}, gamma0, omega);
  const double e1 = r[index_of("e1")], e3 = r[index_of("e3")];
  const double v1 = r[index_of("v1")], v3 = r[index_of("v3")];
  EXPECT_GT(e3, 0.0) << "G'_3 < 0 is strain stiffening";
  EXPECT_LT(v3, 0.0) << "G''_3 < 0 is shear thinning";
  const auto t3 = [](double x) { return 4 * x * x * x - 3 * x; };
  const double rate0 = gamma0 * omega;  // γ̇0 η_s/E*: σ″/E* = γ0 ω̃ Σ (v_n/η_s) T_n(y)
  for (double t = 0.05; t < 2 * kPi; t += 0.37) {
    const double x = std::sin(t), y = std::cos(t);
    EXPECT_NEAR(gamma0 * (e1 * x + e3 * t3(x)), elastic(t), 1e-14) << t;
    EXPECT_NEAR(rate0 * (v1 * y + v3 * t3(y)), viscous(t), 1e-14) << t;
  }
  EXPECT_NEAR(r[index_of("intensity_3")], std::hypot(g3, h3) / std::hypot(g1, h1), 1e-13);
}

std::vector<double> cycle_with(double storage, double loss) {
  std::vector<double> c(oscillation_observable_names().size(), 0.0);
  c[index_of("storage")] = storage;
  c[index_of("loss")] = loss;
  return c;
}

// An exponential approach to a limit cycle with noise: the start-up cycle and
// the transient are dropped, the rest is periodic, its mean within errors.
TEST(PeriodicSummary, DropsTheTransientOfAnApproachToALimitCycle) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-4);
  std::vector<std::vector<double>> cycles;
  cycles.push_back(cycle_with(0.05, 0.01));  // start-up from rest
  for (int k = 1; k < 20; ++k)
    cycles.push_back(cycle_with(0.03 + 0.01 * std::exp(-k / 1.5) + noise(rng), 0.004 + noise(rng)));
  const PeriodicSummary s = summarise_cycles(cycles, 3, 0.01);
  EXPECT_TRUE(s.periodic);
  EXPECT_GE(s.transient_cycles, 3u);
  EXPECT_LE(s.transient_cycles, 10u);
  EXPECT_NEAR(s["storage"].mean, 0.03, 4 * s["storage"].standard_error + 1e-5);
  EXPECT_NEAR(s["loss"].mean, 0.004, 4 * s["loss"].standard_error);
  EXPECT_LT(s.worst_relative_error(), 0.01);
}

// A steady drift (a response still changing, e.g. a sample still ageing or
// yielding further) that is large against the noise is not periodic.
TEST(PeriodicSummary, ADriftIsNotPeriodic) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1e-5);
  std::vector<std::vector<double>> cycles;
  for (int k = 0; k < 12; ++k) cycles.push_back(cycle_with(0.03 - 2e-4 * k + noise(rng), 0.004));
  const PeriodicSummary s = summarise_cycles(cycles, 3, 0.01);
  EXPECT_FALSE(s.periodic);
  EXPECT_GT(s.drift, 3.0);
}

// Identical cycles (the deterministic response below yield) are periodic with
// zero error; too few cycles after the start-up are not.
TEST(PeriodicSummary, IdenticalCyclesArePeriodicAndTooFewAreNot) {
  std::vector<std::vector<double>> cycles(5, cycle_with(0.03, 0.002));
  PeriodicSummary s = summarise_cycles(cycles, 3, 0.01);
  EXPECT_TRUE(s.periodic);
  EXPECT_EQ(s["storage"].standard_error, 0.0);
  cycles.resize(3);
  s = summarise_cycles(cycles, 3, 0.01);
  EXPECT_FALSE(s.periodic);
  cycles.front().back() = std::nan("");
  EXPECT_THROW(summarise_cycles(cycles, 3, 0.01), std::invalid_argument);
}

}  // namespace
}  // namespace softglass::micro
