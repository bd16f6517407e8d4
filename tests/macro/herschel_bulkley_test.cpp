// The Herschel–Bulkley law (macro/material/herschel_bulkley.h): stress and
// inverse flow curve, secant viscosity, the complementary potential Φ, and the
// augmented-Lagrangian local step; the law as the solvers see it (shear_law.h)
// and its regularisations, made by name from their registry.
#include "macro/material/herschel_bulkley.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "common/errors.h"
#include "macro/material/regularised_law.h"
#include "macro/material/shear_law.h"
#include "macro_test_support.h"

namespace softglass::macro {
namespace {

using testing::gauss_kronrod;
using testing::relative_error;

// A spread of laws: shear thinning to thickening, with and without yield stress.
std::vector<HerschelBulkley> laws() {
  std::vector<HerschelBulkley> result;
  for (double tau_y : {0.0, 10.0})
    for (double n : {0.3, 0.5, 1.0, 1.7, 2.0})
      result.push_back({.yield_stress = tau_y, .consistency = 5.0, .flow_index = n});
  return result;
}

TEST(HerschelBulkley, StressIsYieldPlusPower) {
  const HerschelBulkley law{.yield_stress = 10.0, .consistency = 5.0, .flow_index = 0.5};
  EXPECT_DOUBLE_EQ(law.stress(4.0), 10.0 + 5.0 * 2.0);
  EXPECT_EQ(law.stress(0.0), 10.0);  // the limit from above
}

TEST(HerschelBulkley, RateInvertsStressAndVanishesBelowYield) {
  for (const HerschelBulkley& law : laws()) {
    for (double rate : {1e-6, 1e-2, 1.0, 37.0, 1e4}) {
      // Rounding τ costs ε_mach·τ; the inverse amplifies a relative error of
      // τ by its condition number τ/(n(τ − τ_y)), large when Kγ̇ⁿ ≪ τ_y.
      const double tau = law.stress(rate);
      const double condition = tau / (law.flow_index * (tau - law.yield_stress));
      const double tolerance = 8.0 * std::numeric_limits<double>::epsilon() * (1.0 + condition);
      EXPECT_LT(relative_error(law.rate(tau), rate), tolerance) << law.flow_index << " " << rate;
    }
    EXPECT_EQ(law.rate(law.yield_stress), 0.0);
    EXPECT_EQ(law.rate(0.5 * law.yield_stress), 0.0);
  }
}

TEST(HerschelBulkley, ViscosityIsSecantAndDivergesAtRestWhenItShould) {
  for (const HerschelBulkley& law : laws()) {
    for (double rate : {1e-3, 1.0, 50.0}) {
      EXPECT_LT(relative_error(law.viscosity(rate), law.stress(rate) / rate), 1e-14);
    }
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(bingham(1.0, 2.0).viscosity(0.0), inf);
  EXPECT_EQ(power_law(2.0, 0.5).viscosity(0.0), inf);
  EXPECT_EQ(newtonian(2.0).viscosity(0.0), 2.0);
  EXPECT_EQ(power_law(2.0, 1.5).viscosity(0.0), 0.0);
}

TEST(HerschelBulkley, ProximalRateSolvesTheLocalProblem) {
  for (const HerschelBulkley& law : laws()) {
    for (double penalty : {0.0, 0.1, 10.0, 1e4}) {
      for (double chi :
           {0.5 * law.yield_stress, law.yield_stress + 0.01, law.yield_stress + 30.0}) {
        const double s = law.proximal_rate(chi, penalty);
        if (chi <= law.yield_stress) {
          EXPECT_EQ(s, 0.0);
          continue;
        }
        const double residual = law.stress(s) + penalty * s - chi;
        // s to 1e-13 relative; the residual is that times the tangent, ≤ χ.
        EXPECT_LT(std::abs(residual), 1e-12 * chi) << law.flow_index << " " << penalty;
      }
    }
    // Without penalty the step is the inverse flow curve.
    EXPECT_LT(relative_error(law.proximal_rate(law.yield_stress + 7.0, 0.0),
                             law.rate(law.yield_stress + 7.0)),
              1e-12);
  }
  // Bingham: closed form (χ − τ_y)/(μ + r).
  EXPECT_DOUBLE_EQ(bingham(2.0, 3.0).proximal_rate(12.0, 2.0), 2.0);
}

TEST(HerschelBulkley, SpecialCasesAreRestrictions) {
  const HerschelBulkley b = bingham(3.0, 0.2), p = power_law(4.0, 0.4), n = newtonian(0.7);
  EXPECT_EQ(b.flow_index, 1.0);
  EXPECT_EQ(p.yield_stress, 0.0);
  EXPECT_EQ(n.yield_stress, 0.0);
  EXPECT_EQ(n.flow_index, 1.0);
  EXPECT_DOUBLE_EQ(b.stress(5.0), 3.0 + 0.2 * 5.0);
  EXPECT_DOUBLE_EQ(p.stress(2.0), 4.0 * std::pow(2.0, 0.4));
  EXPECT_DOUBLE_EQ(n.stress(3.0), 2.1);
}

// The solvers' interface gives the law's own values, and a regularised law
// tends to the law where it flows (relative error O(ε²) at γ̇ ≫ ε).
TEST(HerschelBulkley, IsTheShearLawTheSolversSee) {
  for (const HerschelBulkley& law : laws()) {
    const std::shared_ptr<const ShearLaw> shear = shear_law(law);
    EXPECT_EQ(shear->yield_stress(), law.yield_stress);
    for (double rate : {1e-3, 1.0, 50.0}) {
      EXPECT_EQ(shear->stress(rate), law.stress(rate));
      EXPECT_EQ(shear->viscosity(rate), law.viscosity(rate));
      EXPECT_EQ(shear->rate(law.stress(rate)), law.rate(law.stress(rate)));
      EXPECT_EQ(shear->proximal_rate(30.0, 2.0), law.proximal_rate(30.0, 2.0));
    }
    for (const std::string& name : regularisations().names()) {
      const auto regularised = make_regularised_law(name, *shear, 1e-6);
      EXPECT_EQ(regularised->name(), name);
      EXPECT_LT(relative_error(regularised->viscosity(10.0).value, law.viscosity(10.0)), 1e-9)
          << name << " n = " << law.flow_index;
    }
  }
}

TEST(HerschelBulkley, UnknownRegularisationNamesTheAllowedOnes) {
  const auto shear = shear_law(bingham(1.0, 1.0));
  try {
    make_regularised_law("smooth", *shear, 1e-3);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "regularisation 'smooth' is unknown; allowed: papanastasiou, bercovier-engelman");
  }
}

}  // namespace
}  // namespace softglass::macro
