// The tabulated law (macro/material/tabulated_law.h) and its interpolant
// (macro/numerics/monotone_cubic.h): exact identities — a power law tabulated
// is that power law, a Herschel–Bulkley table gives Herschel–Bulkley's exact
// torques — the shape the interpolant promises (monotone, no overshoot, C¹),
// the inverses, and the refusals of tables that are no flow curve.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/errors.h"
#include "macro/exact/cone_plate.h"
#include "macro/exact/couette.h"
#include "macro/exact/parallel_plates.h"
#include "macro/exact/pipe.h"
#include "macro/material/material_parameters.h"
#include "macro/material/tabulated_law.h"
#include "macro/numerics/monotone_cubic.h"
#include "macro/numerics/quadrature.h"
#include "macro_test_support.h"

namespace softglass::macro {
namespace {

using testing::relative_error;

std::vector<double> log_spaced(double from, double to, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(from * std::pow(to / from, double(i) / (count - 1)));
  return out;
}

// The Herschel–Bulkley law sampled at `rates`.
FlowTable table_of(const HerschelBulkley& law, const std::vector<double>& rates) {
  FlowTable t{.yield_stress = law.yield_stress, .rates = rates, .stresses = {}};
  for (const double r : rates) t.stresses.push_back(law.stress(r));
  return t;
}

// A flow curve that is no power law: τ = τ_y + 3 γ̇^½ + 0.2 γ̇, its local
// exponent rising from ½ towards 1 across the table.
FlowTable curved_table(double tau_y) {
  FlowTable t{.yield_stress = tau_y, .rates = log_spaced(1e-2, 1e3, 11), .stresses = {}};
  for (const double r : t.rates) t.stresses.push_back(tau_y + 3.0 * std::sqrt(r) + 0.2 * r);
  return t;
}

const HerschelBulkley kLaw{.yield_stress = 10.0, .consistency = 5.0, .flow_index = 0.5};

TEST(MonotoneCubic, ReproducesAStraightLineAndInvertsIt) {
  const std::vector<double> x{-3.0, -1.0, 0.5, 2.0, 7.0};
  std::vector<double> y;
  for (const double v : x) y.push_back(0.4 * v - 1.0);
  const numerics::MonotoneCubic p(x, y);
  for (double v = -3.0; v <= 7.0; v += 0.37) {
    EXPECT_NEAR(p.value(v), 0.4 * v - 1.0, 1e-14) << v;
    EXPECT_NEAR(p.derivative(v), 0.4, 1e-14) << v;
    EXPECT_NEAR(p.inverse(0.4 * v - 1.0), v, 1e-13) << v;
  }
}

// Monotone data with a steep step: the interpolant rises everywhere, stays
// inside each interval's data range (no overshoot), and its slope is
// continuous at the nodes.
TEST(MonotoneCubic, MonotoneWithoutOvershootAndC1) {
  const std::vector<double> x{0.0, 1.0, 2.0, 2.2, 3.0, 5.0}, y{0.0, 0.01, 0.02, 3.0, 3.01, 3.02};
  const numerics::MonotoneCubic p(x, y);
  double previous = p.value(0.0);
  for (int i = 1; i <= 5000; ++i) {
    const double v = 5.0 * i / 5000.0, value = p.value(v);
    EXPECT_GE(value, previous - 1e-15) << v;
    previous = value;
  }
  for (std::size_t k = 0; k + 1 < x.size(); ++k)
    for (int j = 0; j <= 100; ++j) {
      const double value = p.value(x[k] + (x[k + 1] - x[k]) * j / 100.0);
      EXPECT_GE(value, y[k] - 1e-15);
      EXPECT_LE(value, y[k + 1] + 1e-15);
    }
  for (std::size_t k = 1; k + 1 < x.size(); ++k) {
    const double h = 1e-10;  // the jump in the second derivative moves the slope by ~1e-7
    EXPECT_NEAR(p.derivative(x[k] - h), p.derivative(x[k] + h), 1e-5 * (1 + p.slopes()[k])) << k;
    EXPECT_NEAR(p.inverse(y[k]), x[k], 1e-12) << k;
  }
}

// Δ = K γ̇ⁿ is a straight line in (ln γ̇, ln Δ): the table of a Herschel–Bulkley
// law is that law, inside its window and in both extrapolations.
TEST(TabulatedLaw, AHerschelBulkleyTableIsThatLaw) {
  const auto table = tabulated_law(table_of(kLaw, log_spaced(0.1, 100.0, 7)));
  const auto exact = shear_law(kLaw);
  for (const double rate : log_spaced(1e-6, 1e6, 49)) {
    EXPECT_LT(relative_error(table->stress(rate), exact->stress(rate)), 1e-13) << rate;
    EXPECT_LT(relative_error(table->excess_stress(rate), exact->excess_stress(rate)), 1e-12)
        << rate;
    EXPECT_NEAR(table->local_flow_index(rate), 0.5, 1e-12) << rate;
    const double tau = exact->stress(rate);
    EXPECT_LT(relative_error(table->rate(tau), rate), 1e-11) << rate;
    EXPECT_LT(relative_error(table->proximal_rate(tau, 3.0), exact->proximal_rate(tau, 3.0)),
              1e-11)
        << rate;
    const Viscosity a = table->regularised_flow_viscosity(rate, 0.01),
                    b = exact->regularised_flow_viscosity(rate, 0.01);
    EXPECT_LT(relative_error(a.value, b.value), 1e-12) << rate;
    EXPECT_LT(relative_error(a.derivative, b.derivative), 1e-11) << rate;
  }
  EXPECT_EQ(table->rate(kLaw.yield_stress), 0.0);
  EXPECT_EQ(table->proximal_rate(0.5 * kLaw.yield_stress, 1.0), 0.0);
  const auto [lo, hi] = table->flow_index_range();
  EXPECT_NEAR(lo, 0.5, 1e-12);
  EXPECT_NEAR(hi, 0.5, 1e-12);
}

// The generic regularised viscosity Δ(s)/s, s = √(γ̇² + ε²), of a Herschel–
// Bulkley law is K (γ̇² + ε²)^{(n−1)/2} and its derivative, in closed form.
TEST(TabulatedLaw, RegularisedFlowViscosityOfHerschelBulkleyInClosedForm) {
  const auto law = shear_law(kLaw);
  for (const double rate : {0.0, 1e-4, 0.3, 20.0}) {
    const double eps = 0.05, s2 = rate * rate + eps * eps;
    const Viscosity v = law->regularised_flow_viscosity(rate, eps);
    EXPECT_LT(relative_error(v.value, 5.0 * std::pow(s2, -0.25)), 1e-14) << rate;
    EXPECT_NEAR(v.derivative, -0.5 * rate * 5.0 * std::pow(s2, -1.25), 1e-13) << rate;
  }
}

// The exact references of a Herschel–Bulkley table are Herschel–Bulkley's
// (partially yielded Couette, the cone and plate past the yield angle, plates,
// pipe), although they now split their quadratures at the table's nodes.
TEST(TabulatedLaw, ExactReferencesOfAHerschelBulkleyTable) {
  const auto table = tabulated_law(table_of(kLaw, log_spaced(0.1, 100.0, 7)));
  const exact::CouetteCell cell{.inner_radius = 0.020, .outer_radius = 0.030, .length = 1.0};
  const exact::ConePlate cone{.radius = 0.025, .angle = 4.0 * std::numbers::pi / 180.0};
  const exact::ParallelPlates plates{.radius = 0.025, .gap = 1e-3};
  for (const double omega : {1e-3, 0.05, 1.0, 30.0}) {
    EXPECT_LT(relative_error(exact::torque(*table, cell, omega), exact::torque(kLaw, cell, omega)),
              1e-10)
        << omega;
    EXPECT_LT(relative_error(exact::torque(*table, cone, omega), exact::torque(kLaw, cone, omega)),
              1e-10)
        << omega;
    const double t = exact::torque(*table, plates, omega);
    EXPECT_LT(relative_error(t, exact::torque(kLaw, plates, omega)), 1e-10) << omega;
    EXPECT_LT(relative_error(exact::rotation_rate(*table, plates, t), omega), 1e-9) << omega;
  }
  const exact::Pipe pipe{.radius = 0.01, .pressure_gradient = 8000.0};
  EXPECT_LT(relative_error(exact::flow_rate(*table, pipe), exact::flow_rate(kLaw, pipe)), 1e-10);
}

// A curved table (no power law): the Couette rotation rate from the torque by
// exact/couette.h against the same integral taken in the rate instead of the
// stress — ω = ½ ∫ γ̇(τ)/τ dτ = ½ ∫ (γ̇ τ'(γ̇)/τ(γ̇)) dγ̇ over the yielded layer —
// with τ'(γ̇) = Δ(γ̇) n(γ̇)/γ̇ from the law's local flow index.
TEST(TabulatedLaw, CouetteRotationRateOfACurvedTableByTwoQuadratures) {
  const auto law = tabulated_law(curved_table(4.0));
  const exact::CouetteCell cell{.inner_radius = 0.020, .outer_radius = 0.030, .length = 1.0};
  for (const double torque : {0.02, 0.05, 0.5, 20.0}) {
    const double tau1 = exact::shear_stress(cell, torque, cell.inner_radius),
                 tau2 = exact::shear_stress(cell, torque, cell.outer_radius);
    const double lo = law->rate(std::max(tau2, law->yield_stress())), hi = law->rate(tau1);
    std::vector<double> cuts;
    for (const double r : curved_table(4.0).rates) cuts.push_back(r);
    const double by_rate = 0.5 * numerics::integrate(
                                     [&](double g) {
                                       return law->excess_stress(g) * law->local_flow_index(g) /
                                              law->stress(g);
                                     },
                                     lo, hi, cuts);
    EXPECT_LT(relative_error(exact::rotation_rate(*law, cell, torque), by_rate), 1e-9) << torque;
  }
}

// Above and below the window the law is the power law of the end interval,
// continuous with the table there.
TEST(TabulatedLaw, ExtrapolatesWithTheEndExponents) {
  const FlowTable t = curved_table(4.0);
  const auto law = tabulated_law(t);
  const double n_lo = std::log((t.stresses[1] - 4.0) / (t.stresses[0] - 4.0)) /
                      std::log(t.rates[1] / t.rates[0]);
  const double n_hi = std::log((t.stresses[10] - 4.0) / (t.stresses[9] - 4.0)) /
                      std::log(t.rates[10] / t.rates[9]);
  for (const double f : {1e-6, 1e-2, 0.5}) {
    EXPECT_LT(relative_error(law->excess_stress(f * t.rates[0]),
                             (t.stresses[0] - 4.0) * std::pow(f, n_lo)),
              1e-12);
    EXPECT_LT(relative_error(law->excess_stress(t.rates[10] / f),
                             (t.stresses[10] - 4.0) * std::pow(f, -n_hi)),
              1e-12);
  }
  for (std::size_t i = 0; i < t.rates.size(); ++i)
    EXPECT_LT(relative_error(law->stress(t.rates[i]), t.stresses[i]), 1e-14) << i;
  EXPECT_EQ(law->stress(0.0), 4.0);
}

TEST(TabulatedLaw, RefusesTablesThatAreNoFlowCurve) {
  const auto refused = [](FlowTable t, const std::string& words) {
    try {
      tabulated_law(t);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  FlowTable t = curved_table(1.0);
  auto decreasing = t;
  decreasing.stresses[5] = decreasing.stresses[3];
  refused(decreasing, "does not exceed stress 5");
  auto unordered = t;
  std::swap(unordered.rates[2], unordered.rates[3]);
  refused(unordered, "strictly increasing rates");
  auto below_yield = t;
  below_yield.yield_stress = t.stresses[0];
  refused(below_yield, "does not exceed 'yield stress'");
  auto short_table = t;
  short_table.rates.resize(1);
  short_table.stresses.resize(1);
  refused(short_table, "at least 2");
  auto mismatch = t;
  mismatch.stresses.pop_back();
  refused(mismatch, "one stress per rate");
  auto negative_rate = t;
  negative_rate.rates[0] = -1.0;
  refused(negative_rate, "rate 1 = -1");
  // A shear-thickening end steeper than a material file's n ≤ 2.
  FlowTable steep{.yield_stress = 0.0, .rates = {1.0, 2.0, 3.0}, .stresses = {1.0, 2.0, 30.0}};
  refused(steep, "highest interval");
}

// The material fragment of a tabulated law, with normal stresses at the same
// rates, through the reader of every material file.
TEST(TabulatedLaw, ReadFromAMaterialFragment) {
  const Material m = parse_material(
      "subsection material\n set model = tabulated\n set yield stress = 2\n"
      " set rates = 0.1, 1, 10\n set stresses = 3, 5, 9\n set N1 values = 0.5, 1, 3\n"
      " set N1 yield = 0.2\n set source = (c) measured yield stress\nend\n",
      "tabulated.prm");
  EXPECT_EQ(m.model, "tabulated");
  EXPECT_EQ(m.source, "(c) measured yield stress");
  EXPECT_EQ(m.shear->yield_stress(), 2.0);
  EXPECT_NEAR(m.shear->stress(1.0), 5.0, 1e-14);
  EXPECT_NEAR(m.first_normal_stress_difference->value(10.0), 3.0, 1e-14);
  EXPECT_EQ(m.first_normal_stress_difference->value(0.0), 0.2);
  EXPECT_TRUE(m.second_normal_stress_difference->vanishes());
  for (const auto& [text, words] : std::vector<std::pair<std::string, std::string>>{
           {" set yield stress = 2\n set stresses = 3, 5\n", "required entries not set: 'rates'"},
           {" set yield stress = 2\n set rates = 1, 2\n set stresses = 3, 5\n set N2 yield = 1\n",
            "'N2 yield' = 1 is set without 'N2 values'"},
           {" set yield stress = 2\n set rates = 1, 2\n set stresses = 3, 5\n"
            " set N1 values = 1\n",
            "'N1 values' has 1 values"}}) {
    try {
      parse_material("subsection material\n set model = tabulated\n" + text + "end\n", "t.prm");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace softglass::macro
