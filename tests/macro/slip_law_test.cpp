// Slip laws (macro/material/slip_law.h): the power law and its slip yield
// stress form, their inverse, their regularisation (value, consistent
// derivative, second-order error) and the refusal of bad coefficients.
#include "macro/material/slip_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "common/errors.h"
#include "macro_test_support.h"

namespace softglass::macro {
namespace {

using testing::relative_error;

std::unique_ptr<SlipLaw> power(double beta, double p, double yield = 0.0) {
  return make_slip_law("power-law", {.coefficient = beta, .exponent = p, .yield_stress = yield});
}

// V = β (σ − σ_s)^p, written out: σ_w(V) must invert it, and σ_w(0) = σ_s.
TEST(SlipLaw, PowerLawIsTheInverseOfItsSlipVelocity) {
  for (const double p : {0.5, 1.0, 2.0, 3.0}) {
    for (const double yield : {0.0, 4.0}) {
      const auto law = power(2e-6, p, yield);
      EXPECT_EQ(law->stress(0.0), yield);
      EXPECT_EQ(law->velocity(0.5 * yield), 0.0);
      for (const double sigma : {5.0, 30.0, 1e3}) {
        const double v = law->velocity(sigma);
        EXPECT_LT(relative_error(v, 2e-6 * std::pow(sigma - yield, p)), 1e-15) << p;
        EXPECT_LT(relative_error(law->stress(v), sigma), 1e-13) << p << " " << sigma;
      }
    }
  }
}

// The regularised law: odd, its derivative the derivative of its value
// (central differences, h = 1e-6 |V|: truncation and rounding ~1e-10
// relative), finite and positive at V = 0 where the law's is infinite (p > 1)
// or zero (p < 1) or the law jumps (σ_s > 0).
TEST(SlipLaw, RegularisedDerivativeIsConsistent) {
  const double eps = 1e-4;
  for (const double p : {0.5, 1.0, 2.0}) {
    for (const double yield : {0.0, 4.0}) {
      const auto law = power(2e-6, p, yield);
      for (const double v : {-3e-3, -1e-4, 2e-5, 1e-4, 1e-3, 0.1}) {
        const WallStress w = law->regularised(v, eps);
        EXPECT_EQ(law->regularised(-v, eps).value, -w.value);
        const double h = 1e-6 * std::abs(v);
        const double slope =
            (law->regularised(v + h, eps).value - law->regularised(v - h, eps).value) / (2.0 * h);
        EXPECT_LT(relative_error(w.derivative, slope), 1e-7) << p << " " << yield << " " << v;
      }
      const WallStress rest = law->regularised(0.0, eps);
      EXPECT_EQ(rest.value, 0.0);
      EXPECT_GT(rest.derivative, 0.0);
      EXPECT_TRUE(std::isfinite(rest.derivative));
    }
  }
}

// At fixed V the error is second order in ε (slip_law.h:
// σ_w − σ_ε ≈ [σ_s + (1 − m) k V^m] ε²/(2V²)), and exactly zero for the linear
// law without yield stress.
TEST(SlipLaw, RegularisationErrorIsSecondOrder) {
  const double v = 1e-3;
  for (const double yield : {0.0, 4.0}) {
    const auto law = power(2e-6, 2.0, yield);
    const double k = std::pow(2e-6, -0.5), m = 0.5;
    for (const double eps : {1e-5, 1e-6}) {
      const double error = law->stress(v) - law->regularised(v, eps).value;
      const double predicted = (yield + (1.0 - m) * k * std::pow(v, m)) * eps * eps / (2.0 * v * v);
      EXPECT_LT(relative_error(error, predicted), 1e-2) << yield << " " << eps;
    }
  }
  const auto navier = power(2e-6, 1.0);
  EXPECT_LT(relative_error(navier->regularised(v, 1e-2).value, navier->stress(v)), 1e-15);
}

// One line naming the entry of `subsection slip`, its value and what is allowed.
TEST(SlipLaw, BadCoefficientsAreRefusedNamingTheEntry) {
  const auto message = [](double beta, double p, double yield) -> std::string {
    try {
      power(beta, p, yield);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(-1e-6, 2.0, 0.0).find("'coefficient' = -1e-06"), std::string::npos);
  EXPECT_NE(message(0.0, 2.0, 0.0).find("'coefficient' = 0"), std::string::npos);
  EXPECT_NE(message(nan, 2.0, 0.0).find("'coefficient' = nan"), std::string::npos);
  EXPECT_NE(message(1e-6, 0.0, 0.0).find("'exponent' = 0"), std::string::npos);
  EXPECT_NE(message(1e-6, -2.0, 0.0).find("'exponent' = -2"), std::string::npos);
  EXPECT_NE(message(1e-6, nan, 0.0).find("'exponent' = nan"), std::string::npos);
  EXPECT_NE(message(1e-6, 2.0, -1.0).find("'yield stress' = -1"), std::string::npos);
  // β^{−1/p} overflows: 1e-300^{−1/0.1}.
  EXPECT_NE(message(1e-300, 0.1, 0.0).find("'coefficient'"), std::string::npos);
  EXPECT_EQ(message(1e-6, 2.0, 0.0), "accepted");
  EXPECT_THROW(make_slip_law("navier", {.coefficient = 1.0, .exponent = 1.0}), InputError);
}

}  // namespace
}  // namespace softglass::macro
