// The wall slip law of a `micro slip` table (bridge/slip/slip_law.h): the
// reduced power law recovered from synthetic tables (exactly without noise,
// within its reported errors with noise), the SI coefficient against the
// units identity, interpolation in phi, and every refusal of the reader.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <tuple>
#include <random>
#include <string>
#include <vector>

#include "bridge/slip/slip_law.h"
#include "bridge/slip/slip_table.h"
#include "bridge_test_support.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

// A reduced law Ṽ γ̃ = A σ̃^p sampled at wall stresses from 1e-4 to 3e-3 E*.
std::vector<SlipPoint> exact_points(double a, double p, std::size_t n, double relative_error) {
  std::vector<SlipPoint> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 1e-4 * std::pow(30.0, double(i) / double(n - 1));
    const double v = a * std::pow(s, p);
    points.push_back({{s, relative_error * s}, {v, relative_error * v}});
  }
  return points;
}

// The same table as `micro slip` writes it: Ṽ in units of γ̇_app R, so the
// value is (A σ̃^p)/γ̃_app.
std::string slip_csv(const std::vector<double>& phis, const std::vector<double>& a,
                     const std::vector<double>& p) {
  std::string csv =
      "phi,gamma_app,seed,gap,stationary_samples,converged,wall_stress,wall_stress_se,"
      "slip_velocity,slip_velocity_se,bulk_rate,bulk_rate_se\n";
  for (std::size_t j = 0; j < phis.size(); ++j)
    for (const double rate : {1e-6, 1e-5, 1e-4, 1e-3}) {
      const double s = 0.5 * std::sqrt(rate);  // any increasing stress
      const double v = a[j] * std::pow(s, p[j]) / rate;
      csv += fmt::format("{},{},1,1000,250,1,{:.17g},{:.3g},{:.17g},{:.3g},0,0\n", phis[j], rate, s,
                         1e-3 * s, v, 1e-3 * v);
    }
  return csv;
}

SlipTable parse(const std::string& csv) { return read_slip_table(CsvTable::parse(csv, "slip.csv")); }

double no_limit(double) { return std::numeric_limits<double>::infinity(); }

TEST(SlipLaw, RecoversAnExactPowerLaw) {
  const double a = 37.5, p = 1.85;
  const SlipLawFit f = fit_slip_law(exact_points(a, p, 6, 1e-3));
  EXPECT_NEAR(f.log_coefficient.value, std::log(a), 1e-10);
  EXPECT_NEAR(f.exponent.value, p, 1e-10);
  EXPECT_EQ(f.scatter, 0.0);
  EXPECT_LT(f.goodness.chi2, 1e-12);
  EXPECT_EQ(f.goodness.dof, 4);
  EXPECT_EQ(f.points, 6u);
  EXPECT_NEAR(f.stress_min, 1e-4, 1e-16);
  EXPECT_NEAR(f.stress_max, 3e-3, 1e-15);
  // The errors are those of the rows': relative 1e-3 in both coordinates.
  EXPECT_GT(f.exponent.error, 1e-4);
  EXPECT_LT(f.exponent.error, 1e-2);
  EXPECT_GT(f.correlation, 0.9) << "A is the value at sigma~ = 1, beyond the data";
  // The pivot lies inside the data, where the law is best determined.
  EXPECT_GT(f.pivot_stress(), 1e-4);
  EXPECT_LT(f.pivot_stress(), 3e-3);
  EXPECT_LT(f.pivot_error(), f.log_coefficient.error);
  // Two rows: the line through both.
  const SlipLawFit two = fit_slip_law(exact_points(a, p, 2, 1e-3));
  EXPECT_NEAR(two.exponent.value, p, 1e-10);
  EXPECT_EQ(two.goodness.dof, 0);
}

// Over `trials` tables of the law sampled at `rows` stresses, each row
// perturbed by `perturb`: the rms pulls (estimate − truth)/SE of ln A and p,
// the mean scatter τ, and the largest p-value of the rows' own errors.
struct Pulls {
  double log_coefficient = 0, exponent = 0, scatter = 0, p_value = 0;
};
Pulls pulls(double a, double p, std::size_t rows, double relative_error, int trials,
            const std::function<void(SlipPoint&, std::mt19937_64&)>& perturb) {
  std::mt19937_64 rng(7);
  Pulls out;
  for (int t = 0; t < trials; ++t) {
    std::vector<SlipPoint> points = exact_points(a, p, rows, relative_error);
    for (SlipPoint& q : points) perturb(q, rng);
    const SlipLawFit f = fit_slip_law(points);
    const double za = (f.log_coefficient.value - std::log(a)) / f.log_coefficient.error;
    const double zp = (f.exponent.value - p) / f.exponent.error;
    EXPECT_LT(std::abs(zp), 5.0) << "trial " << t;
    out.log_coefficient += za * za / trials;
    out.exponent += zp * zp / trials;
    out.scatter += f.scatter / trials;
    out.p_value = std::max(out.p_value, f.goodness.p_value);
  }
  out.log_coefficient = std::sqrt(out.log_coefficient);
  out.exponent = std::sqrt(out.exponent);
  return out;
}

// Noise drawn from the rows' standard errors, in both coordinates: the
// reported errors are the spread of the estimates (pulls of unit variance).
TEST(SlipLaw, NoisyRowsAreWithinTheirReportedErrors) {
  const double rel = 0.02;
  const Pulls z = pulls(12.0, 1.6, 7, rel, 400, [rel](SlipPoint& q, std::mt19937_64& rng) {
    std::normal_distribution<double> gauss;
    q.stress.value *= std::exp(rel * gauss(rng));
    q.velocity.value *= std::exp(rel * gauss(rng));
    q.stress.error = rel * q.stress.value;
    q.velocity.error = rel * q.velocity.value;
  });
  // Errors rescaled by the scatter where chi2/dof > 1 make the pulls a little
  // narrower than 1; far from 1 would be wrong errors.
  for (const double pull : {z.log_coefficient, z.exponent}) {
    EXPECT_GT(pull, 0.75);
    EXPECT_LT(pull, 1.15);
  }
}

// Rows that scatter about the law far beyond their standard errors (like the
// nearly deterministic sliding plugs of `micro slip`): the scatter is found
// and the errors rest on it.
TEST(SlipLaw, ScatterBeyondTheRowsErrorsIsMeasuredAndCarried) {
  const double tau = 0.05;
  const Pulls z = pulls(5.0, 2.0, 12, 1e-6, 200, [tau](SlipPoint& q, std::mt19937_64& rng) {
    q.velocity.value *= std::exp(tau * std::normal_distribution<double>()(rng));
  });
  EXPECT_LT(z.p_value, 1e-6) << "the rows' own errors do not explain the scatter";
  EXPECT_NEAR(z.scatter, tau, 0.15 * tau);
  EXPECT_GT(z.exponent, 0.8);
  EXPECT_LT(z.exponent, 1.25);
}

// V_s = β σ_w^p in SI must equal Ṽ γ̃ E* R/η_s at σ_w = σ̃_w E*.
TEST(SlipLaw, SiCoefficientObeysTheUnitsIdentity) {
  const double a = 23.0, p = 1.9;
  for (const auto& [e, eta, r] : {std::tuple(3857.26, 0.89e-3, 3.4e-6),
                                  std::tuple(40e3, 1e-3, 1.25e-6), std::tuple(1e6, 2.0, 1e-4)}) {
    const double beta = slip_coefficient_si(a, p, e, eta, r);
    for (const double s : {1e-4, 1e-3, 1e-2}) {
      const double reduced_velocity = a * std::pow(s, p);  // Ṽ γ̃
      const double si_velocity = reduced_velocity * e * r / eta;
      EXPECT_NEAR(beta * std::pow(s * e, p), si_velocity, 1e-12 * si_velocity);
    }
    EXPECT_NEAR(slip_coefficient_si(a, p, e, eta, 2 * r), 2 * beta, 1e-12 * beta) << "beta ~ R";
  }
  // Navier slip (p = 1) does not depend on E*: β = A R/η_s.
  EXPECT_NEAR(slip_coefficient_si(3.0, 1.0, 1234.0, 1e-3, 1e-6), 3.0 * 1e-6 / 1e-3, 1e-15);
  for (const auto& [e, eta, r] : {std::tuple(0.0, 1e-3, 1e-6), std::tuple(4e4, -1e-3, 1e-6),
                                  std::tuple(4e4, 1e-3, 0.0), std::tuple(4e4, 1e-3, -1e-6),
                                  std::tuple(4e4, 1e-3, std::nan(""))})
    EXPECT_THROW(slip_coefficient_si(a, p, e, eta, r), InputError);
}

TEST(SlipLaw, TableRecoveredPerVolumeFractionAndInterpolated) {
  const SlipTable t = parse(slip_csv({0.8, 0.85}, {20.0, 80.0}, {1.9, 1.7}));
  ASSERT_EQ(t.rows.size(), 8u);
  const std::vector<SlipTableFit> fits = fit_slip_table(t, no_limit);
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_NEAR(fits[0].law.exponent.value, 1.9, 1e-9);
  EXPECT_NEAR(std::exp(fits[1].law.log_coefficient.value), 80.0, 1e-7);
  const SlipLawAt mid = slip_law_at(fits, 0.825, false);
  EXPECT_NEAR(mid.exponent.value, 1.8, 1e-9);
  EXPECT_NEAR(mid.log_coefficient.value, 0.5 * (std::log(20.0) + std::log(80.0)), 1e-8);
  EXPECT_FALSE(mid.extrapolated);
  expect_contains(mid.placement, {"interpolated"});
  EXPECT_NEAR(slip_law_at(fits, 0.8, false).exponent.value, 1.9, 1e-9);
  try {
    slip_law_at(fits, 0.9, false);
    ADD_FAILURE() << "phi outside the table";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"phi = 0.9", "0.8 ... 0.85", "--extrapolate"});
  }
  const SlipLawAt out = slip_law_at(fits, 0.9, true);
  EXPECT_TRUE(out.extrapolated);
  EXPECT_NEAR(out.exponent.value, 1.5, 1e-8);
  // One volume fraction: its own law only, or kept as it is when extrapolating.
  const std::vector<SlipTableFit> one =
      fit_slip_table(parse(slip_csv({0.8}, {20.0}, {1.9})), no_limit);
  EXPECT_THROW(slip_law_at(one, 0.85, false), InputError);
  const SlipLawAt kept = slip_law_at(one, 0.85, true);
  EXPECT_NEAR(kept.exponent.value, 1.9, 1e-9);
  expect_contains(kept.placement, {"EXTRAPOLATED", "0.8"});
}

TEST(SlipLaw, StressLimitLeavesRowsOutAndNeedsTwo) {
  const SlipTable t = parse(slip_csv({0.8}, {20.0}, {1.9}));
  // Stresses 0.5 sqrt(rate): 5e-4, 1.58e-3, 5e-3, 1.58e-2.
  const std::vector<SlipTableFit> fits = fit_slip_table(t, [](double) { return 2e-3; });
  EXPECT_EQ(fits[0].law.points, 2u);
  EXPECT_EQ(fits[0].fitted, (std::vector<bool>{true, true, false, false}));
  try {
    fit_slip_table(t, [](double) { return 1e-3; });
    ADD_FAILURE() << "one row below the limit";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"slip.csv", "phi = 0.8", "0.001 E*", "1 usable row", "at least 2"});
  }
}

TEST(SlipLaw, BadTablesAreRefusedNamingThePlace) {
  const std::string good = slip_csv({0.8}, {20.0}, {1.9});
  EXPECT_NO_THROW(parse(good));
  const auto refused = [](const std::string& csv, std::vector<std::string> words) {
    try {
      parse(csv);
      ADD_FAILURE() << "accepted:\n" << csv;
    } catch (const InputError& e) {
      for (const std::string& w : words) expect_contains(e.what(), {w});
    }
  };
  const auto replace = [&good](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  refused(replace("slip_velocity_se", "velocity_se"), {"slip_velocity_se", "missing"});
  refused(replace("wall_stress,", "stress,"), {"'wall_stress' is missing"});
  refused(replace("wall_stress,", "wall_stress [Pa],"), {"wall_stress [Pa]", "E*"});
  refused(replace("bulk_rate,", "wall_stress,"), {"appears twice"});
  refused(replace("0.8,1e-06", "nan,1e-06"), {"line 2", "phi"});
  refused(replace("0.8,1e-06", "1.2,1e-06"), {"line 2", "phi", "(0, 1)"});
  refused(replace("0.8,1e-06", "0.8,0"), {"gamma_app", "> 0"});
  refused(replace("0.8,1e-06,1,1000,250,1,", "0.8,1e-06,1,1000,250,1,-"), {"wall_stress", "> 0"});
  refused(replace("0.8,1e-06,1,1000,250,1,", "0.8,1e-06,1,1000,250,7,"), {"converged", "0 or 1"});
  refused(replace(",0,0\n", ",0,\n"), {"line 2"});
  refused("phi,gamma_app,wall_stress,wall_stress_se,slip_velocity,slip_velocity_se\n",
          {"no rows"});
  // One run listed twice would weigh twice; another packing's run is another datum.
  const std::string first_row = good.substr(good.find('\n') + 1, good.find('\n', good.find('\n') + 1) - good.find('\n'));
  refused(good + first_row, {"line 6", "phi = 0.8, gamma_app = 1e-06, seed 1", "already on line 2", "weigh twice"});
  std::string other_seed = first_row;
  other_seed.replace(other_seed.find(",1,1000,"), 8, ",2,1000,");
  EXPECT_NO_THROW(parse(good + other_seed));
  // A wall slips by at most half the walls' relative velocity: Ṽ ≤ gap/2 (in R).
  refused(replace("0.8,1e-06,1,1000,", "0.8,1e-06,1,2,"), {"line 2", "slip_velocity", "at most gap/2 = 1"});
  // Units, when given, must be the documented ones.
  EXPECT_NO_THROW(parse(replace("wall_stress,", "wall_stress [E*],")));
  // Equal stresses leave p undetermined.
  const SlipTable flat = parse(
      "phi,gamma_app,wall_stress,wall_stress_se,slip_velocity,slip_velocity_se\n"
      "0.8,1e-5,1e-3,1e-6,5,0.01\n0.8,1e-4,1e-3,1e-6,0.5,0.01\n");
  EXPECT_THROW(fit_slip_table(flat, no_limit), InputError);
  // Velocities far beyond reduced units give an A no double can hold: refused, not "inf".
  // ln A = 800 with p = 20: every velocity a double, A = e^800 not one.
  std::vector<SlipPoint> huge;
  for (const double stress : {1e-4, 3e-4, 1e-3, 3e-3}) {
    const double velocity = std::exp(800 + 20 * std::log(stress));
    huge.push_back({{stress, 1e-3 * stress}, {velocity, 1e-3 * velocity}});
  }
  try {
    fit_slip_law(huge);
    ADD_FAILURE() << "A = exp(ln A) beyond the largest double was accepted";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"not a representable number", "reduced units"});
  }
}

}  // namespace
}  // namespace softglass::bridge
