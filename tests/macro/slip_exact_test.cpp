// The exact solutions with wall slip (macro/exact/couette.h, channel.h,
// pipe.h) against independent closed forms: Newtonian bulk with Navier slip
// (p = 1), macro.md's Couette check values plus the slip layers, rigid
// rotation of an unyielded gap, and the no-slip limit β → 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "macro/exact/channel.h"
#include "macro/exact/couette.h"
#include "macro/exact/pipe.h"
#include "macro_test_support.h"

namespace softglass::macro::exact {
namespace {

using testing::relative_error;
constexpr double kPi = std::numbers::pi;

// macro.md's cell and law: τ_y = 10 Pa, K = 5 Pa s^½, n = ½, R1 = 20 mm,
// R2 = 30 mm, L = 1 m.
const HerschelBulkley kLaw{.yield_stress = 10.0, .consistency = 5.0, .flow_index = 0.5};
const CouetteCell kCell{.inner_radius = 0.020, .outer_radius = 0.030, .length = 1.0};

std::unique_ptr<SlipLaw> power(double beta, double p, double yield = 0.0) {
  return make_slip_law("power-law", {.coefficient = beta, .exponent = p, .yield_stress = yield});
}

// Newtonian bulk, Navier slip V = β σ on both cylinders: ω = A/r² + B with
// the slip layers in series with the Margules gap,
//     Ω = T [ (1/R1² − 1/R2²)/(4π μ L) + β/(2π L R1³) + β/(2π L R2³) ].
TEST(CouetteSlip, NewtonianWithNavierSlipInClosedForm) {
  const double mu = 0.3, beta = 1e-4, L = kCell.length, R1 = 0.02, R2 = 0.03;
  const auto navier = power(beta, 1.0);
  const CouetteWalls both{.inner = navier.get(), .outer = navier.get()};
  const double compliance = (1.0 / (R1 * R1) - 1.0 / (R2 * R2)) / (4.0 * kPi * mu * L) +
                            beta / (2.0 * kPi * L * R1 * R1 * R1) +
                            beta / (2.0 * kPi * L * R2 * R2 * R2);
  for (const double omega : {1e-3, 0.7, 40.0}) {
    EXPECT_LT(relative_error(torque(newtonian(mu), kCell, omega, both), omega / compliance), 1e-11)
        << omega;
  }
}

// macro.md's check values (no slip: T = 0.03 N m → Ω = 4.23276e-3 rad/s,
// partially yielded; 0.06 → 0.890221, fully) plus the two slip layers of the
// fixed-load law (p = 2), V/r = β τ(r)²/r at each cylinder; to the six digits
// of the check values (half a unit in the last).
TEST(CouetteSlip, CheckValuesPlusTheSlipLayers) {
  const double beta = 2e-5;
  const auto ehd = power(beta, 2.0);
  const CouetteWalls both{.inner = ehd.get(), .outer = ehd.get()};
  struct Check {
    double torque, bulk, half_unit;
  };
  for (const auto& [t, bulk, half_unit] : {Check{0.03, 4.23276e-3, 0.5e-8}, Check{0.06, 0.890221, 0.5e-6}}) {
    const double tau1 = t / (2.0 * kPi * 0.02 * 0.02), tau2 = t / (2.0 * kPi * 0.03 * 0.03);
    const double slip1 = beta * tau1 * tau1 / 0.02, slip2 = beta * tau2 * tau2 / 0.03;
    EXPECT_NEAR(rotation_rate(kLaw, kCell, t, both), bulk + slip1 + slip2, half_unit) << t;
    EXPECT_NEAR(rotation_rate(kLaw, kCell, t, {.inner = ehd.get()}), bulk + slip1,
                half_unit) << t;
    EXPECT_NEAR(rotation_rate(kLaw, kCell, t, {.outer = ehd.get()}), bulk + slip2,
                half_unit) << t;
    // The material beyond the yield radius turns with the cup's slip layer.
    const double r_c = yield_radius(kLaw, kCell, t);
    if (r_c < kCell.outer_radius) {
      EXPECT_DOUBLE_EQ(angular_velocity(kLaw, kCell, t, 0.5 * (r_c + 0.03), both), slip2);
    }
  }
}

// Below the static yield torque the gap is rigid, and a cell slipping at both
// cylinders turns all the same: Ω = β τ1²/R1 + β τ2²/R2 exactly; its torque
// inverts that, and tends to 0 with Ω (no static torque without a slip yield
// stress). With one: the smallest torque at which anything moves.
TEST(CouetteSlip, UnyieldedGapRotatesRigidly) {
  const double beta = 2e-5, t = 0.02;  // static yield torque 2πL R1² τ_y = 0.0251 N m
  const auto ehd = power(beta, 2.0);
  const CouetteWalls both{.inner = ehd.get(), .outer = ehd.get()};
  const double tau1 = t / (2.0 * kPi * 0.02 * 0.02), tau2 = t / (2.0 * kPi * 0.03 * 0.03);
  const double omega = beta * tau1 * tau1 / 0.02 + beta * tau2 * tau2 / 0.03;
  EXPECT_LT(relative_error(rotation_rate(kLaw, kCell, t, both), omega), 1e-14);
  EXPECT_LT(relative_error(torque(kLaw, kCell, omega, both), t), 1e-11);
  EXPECT_EQ(torque(kLaw, kCell, 0.0, both), 0.0);
  const auto sticky = power(beta, 2.0, 4.0);  // σ_s = 4 Pa on the cup: 2πL R2² σ_s = 0.0226
  EXPECT_DOUBLE_EQ(torque(kLaw, kCell, 0.0, {.outer = sticky.get()}),
                   2.0 * kPi * 0.03 * 0.03 * 4.0);
  EXPECT_EQ(rotation_rate(kLaw, kCell, 0.02, {.outer = sticky.get()}), 0.0);
}

// T(Ω) inverts Ω(T) across the regimes (rigid, partially and fully yielded)
// for either wall and both, and for a bulk law with n > 1.
TEST(CouetteSlip, TorqueInvertsRotationRate) {
  const auto ehd = power(2e-5, 2.0), sticky = power(1e-6, 1.5, 3.0);
  const HerschelBulkley thick{.yield_stress = 3.0, .consistency = 0.1, .flow_index = 1.8};
  for (const HerschelBulkley& law : {kLaw, thick}) {
    for (const CouetteWalls& walls :
         {CouetteWalls{.inner = ehd.get()}, CouetteWalls{.outer = ehd.get()},
          CouetteWalls{.inner = ehd.get(), .outer = ehd.get()},
          CouetteWalls{.inner = sticky.get(), .outer = ehd.get()}}) {
      for (const double t : {0.01, 0.0255, 0.03, 0.06, 0.2, 3.0}) {
        const double omega = rotation_rate(law, kCell, t, walls);
        EXPECT_LT(relative_error(torque(law, kCell, omega, walls), t), 1e-11)
            << law.flow_index << " " << t;
      }
    }
  }
}

// β → 0: the no-slip torque, the difference shrinking in proportion to β.
TEST(CouetteSlip, VanishingSlipCoefficientIsNoSlip) {
  const double no_slip = torque(kLaw, kCell, 0.5);
  double previous = 0.0;
  for (const double beta : {1e-7, 1e-9, 1e-11}) {
    const auto ehd = power(beta, 2.0);
    const double change = relative_error(torque(kLaw, kCell, 0.5, {.inner = ehd.get()}), no_slip);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / change, 100.0, 1.0) << beta;
    }
    previous = change;
  }
  EXPECT_LT(previous, 1e-7);
}

// Plane channel, both walls slipping: Newtonian with V = β σ² in closed form,
// Q = 2GH³/(3μ) + 2H β (GH)²; an HB plug below yield slides whole,
// Q = 2H β (GH)^p with u = V_s everywhere; a slip yield stress above GH holds it.
TEST(ChannelSlip, ClosedFormsAndTheSlidingPlug) {
  const double H = 0.01, beta = 2e-6;
  const auto ehd = power(beta, 2.0);
  const PlaneChannel flowing{.half_height = H, .pressure_gradient = 2000.0};  // τ_w = 20 Pa
  const double mu = 2.0, G = 2000.0;
  EXPECT_LT(relative_error(flow_rate(newtonian(mu), flowing, ehd.get()),
                           2.0 * G * H * H * H / (3.0 * mu) + 2.0 * H * beta * 400.0),
            1e-14);
  const HerschelBulkley stiff = bingham(50.0, 2.0);  // τ_y > τ_w: a plug
  EXPECT_LT(relative_error(flow_rate(stiff, flowing, ehd.get()), 2.0 * H * beta * 400.0), 1e-15);
  for (const double y : {0.0, 0.5 * H, H})
    EXPECT_DOUBLE_EQ(velocity(stiff, flowing, y, ehd.get()), beta * 400.0);
  const auto sticky = power(beta, 2.0, 25.0);
  EXPECT_EQ(flow_rate(stiff, flowing, sticky.get()), 0.0);
  // HB above yield: the no-slip profile shifted by V_s(GH).
  const HerschelBulkley hb{.yield_stress = 5.0, .consistency = 2.0, .flow_index = 0.5};
  for (const double y : {0.0, 0.3 * H, H})
    EXPECT_DOUBLE_EQ(velocity(hb, flowing, y, ehd.get()), velocity(hb, flowing, y) + beta * 400.0);
}

// The pipe likewise: Q = πR⁴G/(8μ) + πR² V_s(GR/2), Newtonian with Navier slip
// (a slip length b = βμ: Q = πR⁴G/(8μ) (1 + 4b/R)).
TEST(PipeSlip, NewtonianWithNavierSlip) {
  const double R = 0.01, G = 4000.0, mu = 2.0, beta = 1e-4;
  const auto navier = power(beta, 1.0);
  EXPECT_LT(relative_error(flow_rate(newtonian(mu), Pipe{.radius = R, .pressure_gradient = G},
                                     navier.get()),
                           kPi * R * R * R * R * G / (8.0 * mu) * (1.0 + 4.0 * beta * mu / R)),
            1e-14);
}

}  // namespace
}  // namespace softglass::macro::exact
