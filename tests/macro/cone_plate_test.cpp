// Cone and plate (macro/exact/cone_plate.h): the exact solution for any angle
// against closed forms (Newtonian, power law n = 1/2) and an independent
// quadrature (Herschel–Bulkley), macro.md's Newtonian check value, the
// small-angle limit, the velocity field, the inverse T(Ω), the normal force.
#include "macro/exact/cone_plate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "macro_test_support.h"

namespace softglass::macro::exact {
namespace {

using testing::gauss_kronrod;
using testing::relative_error;

constexpr double kDegree = std::numbers::pi / 180.0;
const HerschelBulkley kLaw{.yield_stress = 10.0, .consistency = 5.0, .flow_index = 0.5};

ConePlate cone(double degrees) { return {.radius = 0.025, .angle = degrees * kDegree}; }

double plate_stress(const ConePlate& c, double torque) {
  return 3.0 * torque / (2.0 * std::numbers::pi * std::pow(c.radius, 3));
}

TEST(ConePlate, NewtonianCheckValueOfTheSpec) {
  // T_exact/T_small = 0.999391 at 2°, to half a unit in the last digit.
  const HerschelBulkley water = newtonian(1e-3);
  const double omega = 3.0;
  EXPECT_NEAR(torque(water, cone(2.0), omega) / small_angle_torque(water, cone(2.0), omega),
              0.999391, 0.5e-6);
}

// ∫₀^β sec³ψ dψ = ½[sec β tan β + ln(sec β + tan β)].
TEST(ConePlate, NewtonianClosedFormAtAnyAngle) {
  const double mu = 0.7, torque_value = 2e-3;
  for (double degrees : {1.0, 2.0, 4.0, 30.0, 60.0}) {
    const double b = degrees * kDegree, sec = 1.0 / std::cos(b), tan = std::tan(b);
    const double integral = 0.5 * (sec * tan + std::log(sec + tan));
    const double omega = plate_stress(cone(degrees), torque_value) / mu * integral;
    // Smooth integrand, quadrature asked 1e-10, measured ~1e-15.
    EXPECT_LT(relative_error(rotation_rate(newtonian(mu), cone(degrees), torque_value), omega),
              1e-12)
        << degrees;
  }
}

// Power law n = 1/2: γ̇ = (τ/K)², Ω = (τ_p/K)² ∫₀^β sec⁵ψ dψ,
// ∫ sec⁵ = ¼ sec³ tan + ⅜ sec tan + ⅜ ln(sec + tan).
TEST(ConePlate, PowerLawClosedForm) {
  const HerschelBulkley law = power_law(5.0, 0.5);
  for (double degrees : {2.0, 10.0, 45.0}) {
    const double b = degrees * kDegree, sec = 1.0 / std::cos(b), tan = std::tan(b);
    const double integral = 0.25 * std::pow(sec, 3) * tan + 0.375 * sec * tan +
                            0.375 * std::log(sec + tan);
    const double tau_p = plate_stress(cone(degrees), 1e-3);
    EXPECT_LT(relative_error(rotation_rate(law, cone(degrees), 1e-3),
                             std::pow(tau_p / 5.0, 2.0) * integral),
              1e-12)
        << degrees;
  }
}

// Herschel–Bulkley against Gauss–Kronrod of macro.md's form in θ, cut where
// τ_p/sin²θ = τ_y: partially yielded (τ_p < τ_y < τ_p/cos²β) and fully yielded.
TEST(ConePlate, HerschelBulkleyAgainstIndependentQuadrature) {
  const ConePlate c = cone(10.0);
  for (double tau_p : {9.9, 9.99, 10.0, 12.0, 50.0}) {
    const double torque_value = 2.0 * std::numbers::pi * std::pow(c.radius, 3) * tau_p / 3.0;
    const double theta_lo = std::numbers::pi / 2 - c.angle;
    const double theta_y = tau_p >= 10.0 ? std::numbers::pi / 2 : std::asin(std::sqrt(tau_p / 10.0));
    const double reference = gauss_kronrod(
        [&](double theta) {
          const double s = std::sin(theta);
          return kLaw.rate(tau_p / (s * s)) / s;
        },
        theta_lo, theta_y);
    EXPECT_LT(relative_error(rotation_rate(kLaw, c, torque_value), reference), 1e-10) << tau_p;
  }
}

TEST(ConePlate, NoFlowBelowOnset) {
  // Flow starts when the stress on the cone, τ_p/cos²β, reaches τ_y.
  const ConePlate c = cone(4.0);
  const double onset_stress = 10.0 * std::pow(std::cos(c.angle), 2);
  const double onset_torque = 2.0 * std::numbers::pi * std::pow(c.radius, 3) * onset_stress / 3.0;
  EXPECT_EQ(rotation_rate(kLaw, c, onset_torque), 0.0);
  EXPECT_GT(rotation_rate(kLaw, c, 1.001 * onset_torque), 0.0);
  EXPECT_NEAR(yield_angle(kLaw, c, onset_torque), c.angle, 1e-12);
  EXPECT_DOUBLE_EQ(torque(kLaw, c, 0.0), onset_torque);
}

// T_exact/T_small − 1 = c(γ̇) β² + O(β⁴) at a fixed nominal rate γ̇ = Ω/β
// (c depends on γ̇ unless the law is a power law): halving β quarters the
// deviation. The ratio at (β, β/2) is 4 + O(β²); 1 % covers β ≤ 8°.
TEST(ConePlate, SmallAngleLimitIsSecondOrder) {
  for (const HerschelBulkley& law : {kLaw, power_law(5.0, 0.5), bingham(10.0, 0.2)}) {
    const auto deviation = [&](double degrees) {
      const double omega = 20.0 * degrees * kDegree;
      return torque(law, cone(degrees), omega) / small_angle_torque(law, cone(degrees), omega) - 1.0;
    };
    for (double degrees : {8.0, 4.0, 2.0}) {
      EXPECT_NEAR(deviation(degrees) / deviation(degrees / 2.0), 4.0, 0.04)
          << law.flow_index << " " << degrees;
    }
  }
}

TEST(ConePlate, TorqueInvertsRotationRate) {
  for (const HerschelBulkley& law : {kLaw, newtonian(0.1), power_law(5.0, 0.3),
                                     HerschelBulkley{.yield_stress = 3.0, .consistency = 0.1,
                                                     .flow_index = 1.8}}) {
    for (double degrees : {0.5, 2.0, 20.0}) {
      for (double omega : {1e-4, 0.3, 10.0, 500.0}) {
        const double t = torque(law, cone(degrees), omega);
        // Root to 1e-13 on a quadrature good to ~1e-14; conditioning near
        // onset (Ω = 1e-4 with yield stress) leaves 1e-10.
        EXPECT_LT(relative_error(rotation_rate(law, cone(degrees), t), omega), 1e-10)
            << law.flow_index << " " << degrees << " " << omega;
      }
    }
  }
}

TEST(ConePlate, AngularVelocityProfile) {
  const ConePlate c = cone(6.0);
  const double t = torque(kLaw, c, 2.0);
  EXPECT_EQ(angular_velocity(kLaw, c, t, 0.0), 0.0);
  EXPECT_NEAR(angular_velocity(kLaw, c, t, c.angle), 2.0, 2e-10);
  // γ̇ = cos ψ dω/dψ is the flow curve at τ_p/cos²ψ: central differences with
  // h = 1e-7 rad (truncation ~h² ~ 1e-14, rounding ~ε ω/h ~ 1e-9 relative).
  const double tau_p = plate_stress(c, t), h = 1e-7;
  for (double psi : {0.01, 0.05, 0.1}) {
    const double slope =
        (angular_velocity(kLaw, c, t, psi + h) - angular_velocity(kLaw, c, t, psi - h)) / (2.0 * h);
    const double rate = kLaw.rate(tau_p / std::pow(std::cos(psi), 2));
    EXPECT_LT(relative_error(std::cos(psi) * slope, rate), 1e-6) << psi;
  }
  // Partially yielded: a layer on the plate rests.
  // τ_y cos²β < τ_p = 9.95 Pa < τ_y.
  const double slow = 2.0 * std::numbers::pi * std::pow(c.radius, 3) * 9.95 / 3.0;
  const double psi_y = yield_angle(kLaw, c, slow);
  EXPECT_GT(psi_y, 0.0);
  EXPECT_LT(psi_y, c.angle);
  EXPECT_EQ(angular_velocity(kLaw, c, slow, 0.99 * psi_y), 0.0);
  EXPECT_GT(angular_velocity(kLaw, c, slow, 0.5 * (psi_y + c.angle)), 0.0);
}

TEST(ConePlate, NormalForceFromN1) {
  const NormalStressLaw n1{.yield = 2.0, .consistency = 0.9, .flow_index = 0.5};
  const ConePlate c = cone(2.0);
  const double omega = 4.0 * c.angle;  // γ̇ = 4/s, N1 = 2 + 0.9·2 = 3.8 Pa
  EXPECT_DOUBLE_EQ(normal_force(*normal_stress_curve(n1), c, omega), std::numbers::pi * 0.025 * 0.025 * 3.8 / 2.0);
}

}  // namespace
}  // namespace softglass::macro::exact
