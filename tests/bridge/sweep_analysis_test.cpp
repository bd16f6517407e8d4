// `bridge fit` on synthetic sweeps with known parameters: recovery within the
// reported errors, the bootstrap's bias correction, determinism, refusals and
// warnings.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "bridge/output/tables.h"
#include "bridge/sweep/analysis.h"
#include "bridge_test_support.h"
#include "common/csv_table.h"
#include "common/errors.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;
using testing::SyntheticTruth;

SweepAnalysis analyse(const testing::SyntheticSweep& s, std::size_t replicates = 400,
                      bool packings = true) {
  const Sweep sweep = make_sweep(s.table);
  const auto resampler =
      packings ? make_packing_resampler(sweep, s.runs, "runs") : make_parametric_resampler(sweep);
  return analyse_sweep(sweep, *resampler, {replicates, 1});
}

// Within 4 reported standard errors: for ~70 estimates at once, a band that a
// correct error misses with probability 70 × 6e-5 ≈ 0.4 %. (Whether the errors
// are the right size is coverage_test.cpp's question.)
void expect_within(double estimate, double error, double truth, const std::string& what) {
  EXPECT_LT(std::abs(estimate - truth), 4.0 * error)
      << what << ": " << estimate << " ± " << error << ", truth " << truth;
}

TEST(SweepAnalysis, RecoversTheSyntheticParametersWithinTheirErrors) {
  const SyntheticTruth t;
  const SweepAnalysis a = analyse(testing::make_synthetic_sweep(t, 11));
  const SweepFit &v = a.estimate.fit, &e = a.uncertainty.error;
  for (std::size_t j = 0; j < t.phi.size(); ++j) {
    const GroupFit &g = v.groups[j], &s = e.groups[j];
    const std::string at = "phi " + std::to_string(t.phi[j]);
    expect_within(g.hb[0]->yield, s.hb[0]->yield, t.sigma_yield(j), at + " sigma_y");
    expect_within(g.hb[0]->consistency, s.hb[0]->consistency, t.k * t.modulus[j], at + " k_sigma");
    expect_within(g.hb[0]->exponent, s.hb[0]->exponent, 0.5, at + " m");
    expect_within(g.yield_strain, s.yield_strain, t.yield_strain[j], at + " gamma_y");
    expect_within(g.modulus, s.modulus, t.modulus[j], at + " G0");
    for (Quantity q : {Quantity::N1, Quantity::N2}) {
      expect_within(g.hb[index(q)]->yield, s.hb[index(q)]->yield, t.normal_yield(j, q),
                    at + " N_y");
      expect_within(g.hb[index(q)]->exponent, s.hb[index(q)]->exponent, 0.5, at + " N m");
    }
    expect_within(g.hb[3]->yield, s.hb[3]->yield, t.force_yield * t.modulus[j], at + " f_y");
    expect_within(g.hb[3]->exponent, s.hb[3]->exponent, 0.5, at + " f m");
    expect_within(*g.force_yield, *s.force_yield, t.force_yield * t.modulus[j],
                  at + " f_y (m = 1/2)");
    expect_within(*g.force_slope, *s.force_slope, t.force_slope * t.modulus[j], at + " k_f");
    // Each φ's own constants, with the universal laws' signs (k″ > 0 for a falling N2).
    expect_within(*g.own_k[0], *s.own_k[0], t.k, at + " own k");
    expect_within(*g.own_k[1], *s.own_k[1], t.k_N1, at + " own k'");
    expect_within(*g.own_k[2], *s.own_k[2], t.k_N2, at + " own k''");
  }
  expect_within(*v.k[0], *e.k[0], t.k, "k");
  expect_within(*v.k[1], *e.k[1], t.k_N1, "k'");
  expect_within(*v.k[2], *e.k[2], t.k_N2, "k''");
  expect_within(v.mean_exponent, e.mean_exponent, 0.5, "mean m");
  // The errors are useful, not merely large: k to a few per cent with 5 packings.
  EXPECT_LT(*e.k[0], 0.05 * t.k);
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2})
    EXPECT_GT(a.collapse[index(q)]->p_value, 1e-3) << "a universal law collapses";
  for (const std::string& w : a.warnings) ADD_FAILURE() << "unexpected warning: " << w;
}

// The bias-corrected packing bootstrap reproduces the standard error of a mean
// of K packings exactly (in the limit of many replicates): for G0, s/√K.
// The points table's collapse ordinates (Fig. 4): σ/σ_y, N1/σ_y and −N2/σ_y,
// each scaled by the universal σ_y of its φ, so −N2/σ_y is positive.
TEST(SweepAnalysis, PointsTableScalesEveryStressBySigmaY) {
  const SyntheticTruth t;
  const SweepAnalysis a = analyse(testing::make_synthetic_sweep(t, 11), 20);
  const CsvTable table = CsvTable::parse(points_table(a, {}), "points");
  const auto column = [&](const char* name) {
    const std::optional<std::size_t> c = table.find(name);
    EXPECT_TRUE(c.has_value()) << name;
    return c.value_or(0);
  };
  ASSERT_EQ(table.rows(), a.sweep.points());
  for (std::size_t row = 0; row < table.rows(); ++row) {
    const std::size_t j = find_group(a.sweep, table.number(row, column("phi [1]")));
    ASSERT_LT(j, a.sweep.groups.size());
    const double sigma_y = *a.estimate.fit.groups[j].universal_yield[index(Quantity::sigma)];
    // The CSV carries 10 significant digits.
    const auto expect_ratio = [&](const char* ratio, const char* value, double sign) {
      const double expected = sign * table.number(row, column(value)) / sigma_y;
      EXPECT_NEAR(table.number(row, column(ratio)), expected, 1e-8 * std::abs(expected)) << ratio;
    };
    expect_ratio("sigma_ratio [1]", "sigma [E*]", 1.0);
    expect_ratio("N1_ratio [1]", "N1 [E*]", 1.0);
    expect_ratio("N2_ratio [1]", "N2 [E*]", -1.0);
    EXPECT_GT(table.number(row, column("N2_ratio [1]")), 0.0);
  }
}

TEST(SweepAnalysis, PackingBootstrapReproducesTheStandardErrorOfAMean) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 5);
  const SweepAnalysis a = analyse(s, 4000);
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    // 4000 replicates: the sd is known to 1/√8000 ≈ 1.1 %; allow 5 %.
    EXPECT_NEAR(a.uncertainty.error.groups[j].modulus / a.sweep.groups[j].modulus.error, 1.0, 0.05);
  }
}

TEST(SweepAnalysis, ParametricAndPackingBootstrapsAgree) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 6);
  const SweepAnalysis packing = analyse(s), parametric = analyse(s, 400, false);
  EXPECT_NE(packing.method, parametric.method);
  // Two estimates of one standard error, each from 400 replicates (±3.5 %) and
  // different noise models; they agree within 25 %.
  EXPECT_NEAR(*parametric.uncertainty.error.k[0] / *packing.uncertainty.error.k[0], 1.0, 0.25);
  EXPECT_NEAR(parametric.uncertainty.error.groups[2].hb[0]->yield /
                  packing.uncertainty.error.groups[2].hb[0]->yield,
              1.0, 0.25);
}

TEST(SweepAnalysis, IsDeterministicWhateverTheNumberOfThreads) {
  const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 8);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SweepAnalysis one = analyse(s, 50);
  omp_set_num_threads(std::max(2, threads));
  const SweepAnalysis many = analyse(s, 50);
  omp_set_num_threads(threads);
  EXPECT_EQ(*one.uncertainty.error.k[0], *many.uncertainty.error.k[0]);
  EXPECT_EQ(one.uncertainty.error.groups[1].hb[1]->exponent,
            many.uncertainty.error.groups[1].hb[1]->exponent);
}

TEST(SweepAnalysis, RefusesAStressWithoutYieldPlateau) {
  SyntheticTruth t;
  t.yield_strain[2] = 1e-6;  // φ = 0.80: σ_y ≈ 0, a power-law fluid
  try {
    analyse(testing::make_synthetic_sweep(t, 1), 20);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"phi = 0.8, sigma", "yield"});
  }
}

TEST(SweepAnalysis, WarnsWhenTheVolumeFractionsDoNotCollapse) {
  SyntheticTruth t;
  const testing::SyntheticSweep base = testing::make_synthetic_sweep(t, 2);
  // Steeper rate terms at high φ: k_σ/G0 from 56 to 104, not one k.
  testing::SyntheticSweep s = base;
  for (StatePoint& p : s.table.points) {
    const double factor = 1.0 + 3.0 * (p.phi - 0.8);
    const double yield = t.sigma_yield(std::size_t(std::lround((p.phi - 0.7) / 0.05)));
    Estimate& sigma = *p.values[index(Quantity::sigma)];
    sigma.value = yield + factor * (sigma.value - yield);
    sigma.error *= factor;
  }
  const SweepAnalysis a =
      analyse_sweep(make_sweep(s.table), *make_parametric_resampler(make_sweep(s.table)), {200, 1});
  EXPECT_LT(a.collapse[0]->p_value, 1e-3);
  bool warned = false;
  for (const std::string& w : a.warnings)
    warned = warned || w.find("do not collapse") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SweepAnalysis, WarnsAboutPoorlyDeterminedNormalStresses) {
  SyntheticTruth t;
  t.normal_noise = 0.6;  // N1, N2 scattered by 60 % per run
  const SweepAnalysis a = analyse(testing::make_synthetic_sweep(t, 4), 200);
  bool warned = false;
  for (const std::string& w : a.warnings)
    warned = warned || w.find("poorly determined") != std::string::npos;
  EXPECT_TRUE(warned);
}

// Runs that did not meet their stopping rule (`converged` < `packings`) are named.
TEST(SweepAnalysis, WarnsAboutStatePointsWithUnconvergedRuns) {
  testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 2);
  for (StatePoint& p : s.table.points) p.converged = p.packings;
  const auto warnings = [&] {
    const Sweep sweep = make_sweep(s.table);
    return analyse_sweep(sweep, *make_packing_resampler(sweep, s.runs, "runs"), {50, 1}).warnings;
  };
  EXPECT_TRUE(warnings().empty());
  s.table.points[13].converged = 3;  // φ = 0.75, the third rate
  const std::vector<std::string> w = warnings();
  ASSERT_EQ(w.size(), 1u);
  expect_contains(w[0],
                  {"1 state point(s)", "stopping rule", "phi = 0.75, gamma~ = 1e-08: 3 of 5"});
  for (StatePoint& p : s.table.points) p.converged = 0;  // nothing stationary
  expect_contains(warnings().front(), {"55 state point(s)", "0 of 5", "and 50 more"});
}

}  // namespace
}  // namespace softglass::bridge
