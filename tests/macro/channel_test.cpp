// Plane channel (macro/exact/channel.h): the closed-form flow rate against
// direct integration of the velocity profile, the profile against direct
// integration of the flow curve, and the Bingham, power-law and Newtonian
// limits.
#include "macro/exact/channel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "macro_test_support.h"

namespace softglass::macro::exact {
namespace {

using testing::gauss_kronrod;
using testing::relative_error;

const PlaneChannel kChannel{.half_height = 0.01, .pressure_gradient = 2000.0};  // τ_w = 20 Pa

std::vector<HerschelBulkley> laws() {
  std::vector<HerschelBulkley> result;
  for (double tau_y : {0.0, 2.0, 10.0, 19.0})
    for (double n : {0.3, 0.5, 1.0, 1.6}) result.push_back({tau_y, 5.0, n});
  return result;
}

// Q = 2∫₀^H u dy with u from velocity(); the profile has a kink at the plug edge
// y0, so the oracle integrates [0, y0] and [y0, H] separately. Both sides are
// accurate to ~1e-15; 1e-12 allows for Gauss–Kronrod at the endpoint singularity
// of (y − y0)^{1/n+1}.
TEST(Channel, FlowRateIsTheIntegralOfTheProfile) {
  for (const HerschelBulkley& law : laws()) {
    const double y0 = plug_half_width(law, kChannel), H = kChannel.half_height;
    const auto u = [&](double y) { return velocity(law, kChannel, y); };
    const double integral = 2.0 * (gauss_kronrod(u, 0.0, y0) + gauss_kronrod(u, y0, H));
    EXPECT_LT(relative_error(flow_rate(law, kChannel), integral), 1e-12)
        << law.yield_stress << " " << law.flow_index;
  }
}

// u(y) = ∫_{|y|}^H γ̇(G s) ds, straight from the flow curve (no slip, τ = G|y|).
TEST(Channel, ProfileIntegratesTheFlowCurve) {
  const double G = kChannel.pressure_gradient, H = kChannel.half_height;
  for (const HerschelBulkley& law : laws()) {
    const double y0 = plug_half_width(law, kChannel);
    for (double y : {0.0, 0.002, -0.005, 0.0095}) {
      const double from = std::max(std::abs(y), y0);
      const double reference = gauss_kronrod([&](double s) { return law.rate(G * s); }, from, H);
      EXPECT_LT(relative_error(velocity(law, kChannel, y), reference), 1e-12)
          << law.yield_stress << " " << law.flow_index << " " << y;
    }
    EXPECT_EQ(velocity(law, kChannel, H), 0.0);
    // Rigid plug: the centreline velocity holds out to y0.
    EXPECT_EQ(velocity(law, kChannel, 0.5 * y0), velocity(law, kChannel, 0.0));
  }
}

TEST(Channel, PlugAndNoFlow) {
  EXPECT_DOUBLE_EQ(plug_half_width(bingham(10.0, 1.0), kChannel), 0.005);
  EXPECT_EQ(plug_half_width(bingham(30.0, 1.0), kChannel), kChannel.half_height);
  EXPECT_EQ(flow_rate(bingham(20.0, 1.0), kChannel), 0.0);  // φ = 1
  EXPECT_EQ(flow_rate(bingham(30.0, 1.0), kChannel), 0.0);
  EXPECT_EQ(velocity(bingham(30.0, 1.0), kChannel, 0.0), 0.0);
}

// Limits written from the textbooks, not from the general formula.
TEST(Channel, BinghamPowerLawAndNewtonianLimits) {
  const double G = kChannel.pressure_gradient, H = kChannel.half_height, tau_w = G * H;
  const double mu = 0.8;
  // Newtonian: Q = 2GH³/(3μ), u = G(H² − y²)/(2μ).
  EXPECT_LT(relative_error(flow_rate(newtonian(mu), kChannel), 2.0 * G * H * H * H / (3.0 * mu)),
            1e-14);
  EXPECT_LT(relative_error(velocity(newtonian(mu), kChannel, 0.003),
                           G * (H * H - 0.003 * 0.003) / (2.0 * mu)),
            1e-14);
  // Bingham (Buckingham): Q = (2GH³/3μ)(1 − 3φ/2 + φ³/2).
  for (double phi : {0.1, 0.5, 0.9}) {
    const double expected = 2.0 * G * H * H * H / (3.0 * mu) * (1.0 - 1.5 * phi + 0.5 * phi * phi * phi);
    EXPECT_LT(relative_error(flow_rate(bingham(phi * tau_w, mu), kChannel), expected), 1e-13) << phi;
  }
  // Power law: Q = 2H² (τ_w/K)^{1/n} n/(2n+1).
  for (double n : {0.3, 0.5, 1.7}) {
    const double expected = 2.0 * H * H * std::pow(tau_w / 5.0, 1.0 / n) * n / (2.0 * n + 1.0);
    EXPECT_LT(relative_error(flow_rate(power_law(5.0, n), kChannel), expected), 1e-13) << n;
  }
}

// τ_y → 0 approaches the power law continuously: Q changes by O(φ).
TEST(Channel, VanishingYieldStressGivesThePowerLaw) {
  const double power = flow_rate(power_law(5.0, 0.5), kChannel);
  for (double tau_y : {1e-3, 1e-6, 1e-9}) {
    const double q = flow_rate(HerschelBulkley{tau_y, 5.0, 0.5}, kChannel);
    EXPECT_LT(relative_error(q, power), 10.0 * tau_y / wall_stress(kChannel)) << tau_y;
  }
}

}  // namespace
}  // namespace softglass::macro::exact
