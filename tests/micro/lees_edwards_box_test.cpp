// Lees–Edwards cell: wrapping, nearest images and velocities across the gradient
// boundary at strain 0, 0.5 and after many box lengths.
#include <gtest/gtest.h>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {
namespace {

constexpr double kL = 10.0;

TEST(LeesEdwardsBox, OffsetIsStrainFractionTimesSide) {
  LeesEdwardsBox box(kL);
  EXPECT_EQ(box.image_offset(), 0.0);
  box.set_strain(0.5);
  EXPECT_DOUBLE_EQ(box.image_offset(), 5.0);
  box.set_strain(1234.25);  // many box lengths: the offset keeps full precision
  EXPECT_DOUBLE_EQ(box.image_offset(), 2.5);
  EXPECT_DOUBLE_EQ(box.strain(), 1234.25);
}

TEST(LeesEdwardsBox, AdvancingInSmallStepsMatchesSettingTheStrain) {
  LeesEdwardsBox stepped(kL);
  for (int k = 0; k < 1000000; ++k) stepped.advance_strain(1e-3);  // 1000 strain units
  LeesEdwardsBox direct(kL);
  direct.set_strain(1000.0);
  EXPECT_NEAR(stepped.strain(), 1000.0, 1e-9);
  // the offset is periodic in the strain with period 1
  const double d = std::abs(stepped.image_offset() - direct.image_offset());
  EXPECT_LT(std::min(d, kL - d), 1e-8);
}

TEST(LeesEdwardsBox, WrappingThroughTheTopShiftsBackByTheOffset) {
  for (double strain : {0.0, 0.5, 37.3}) {
    LeesEdwardsBox box(kL);
    box.set_strain(strain);
    // A particle leaving through the top enters at the bottom, shifted by −δ in x.
    Vec3 x(3.0, kL + 0.25, 4.0);
    box.wrap(x);
    const double expected_x = std::fmod(3.0 - box.image_offset() + 2 * kL, kL);
    EXPECT_NEAR(x.x(), expected_x, 1e-12) << "strain " << strain;
    EXPECT_NEAR(x.y(), 0.25, 1e-12);
    EXPECT_NEAR(x.z(), 4.0, 1e-12);
    // And back through the bottom.
    Vec3 y(expected_x, -0.25, 4.0);
    box.wrap(y);
    EXPECT_NEAR(y.y(), kL - 0.25, 1e-12);
    EXPECT_NEAR(std::fmod(y.x() - expected_x - box.image_offset() + 3 * kL, kL), 0.0, 1e-12);
  }
}

TEST(LeesEdwardsBox, NearestImageAcrossTheGradientBoundary) {
  for (double strain : {0.0, 0.5, 1e4 + 0.3}) {
    LeesEdwardsBox box(kL);
    box.set_strain(strain);
    const double delta = box.image_offset();
    // β near the bottom, α near the top: the image of β above sits at
    // (x_β + δ, y_β + L), 1 apart in y from α when placed right above it.
    const Vec3 beta(std::fmod(2.0 + 10 * kL, kL), 0.5, 5.0);
    const Vec3 alpha(std::fmod(beta.x() + delta + 0.3, kL), kL - 0.5, 5.2);
    const Vec3 d = box.minimum_image(alpha - beta);
    EXPECT_NEAR(d.x(), 0.3, 1e-9) << "strain " << strain;
    EXPECT_NEAR(d.y(), -1.0, 1e-12);
    EXPECT_NEAR(d.z(), 0.2, 1e-12);
    // antisymmetric
    const Vec3 back = box.minimum_image(beta - alpha);
    EXPECT_NEAR((d + back).norm(), 0.0, 1e-9);
  }
}

TEST(LeesEdwardsBox, ImageVelocityJumpIsShearRateTimesSide) {
  // With u = γ̇ y e_x inside the cell, the image above moves at γ̇ (y + L): the
  // relative velocity of α and the nearest image of β is γ̇ d_y e_x, which is what
  // the engine uses with the nearest-image separation d.
  LeesEdwardsBox box(kL);
  box.set_strain(0.5);
  const Vec3 alpha(1.0, kL - 0.4, 1.0), beta(1.0, 0.3, 1.0);
  const Vec3 d = box.minimum_image(alpha - beta);  // β's image above
  const double u_alpha = alpha.y(), u_beta_image = beta.y() + kL;
  EXPECT_NEAR(u_alpha - u_beta_image, d.y(), 1e-12);
}

}  // namespace
}  // namespace softglass::micro
