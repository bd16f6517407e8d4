// From a measured curve to angular velocities and torques: the instrument's
// conversions are inverted exactly, measured values are kept as they are, and
// the rate window and the refusals work.
#include <gtest/gtest.h>

#include "common/csv_table.h"
#include "common/errors.h"
#include "macro/app/measured_torques.h"

namespace softglass::macro::app {
namespace {

const InstrumentConstants kConstants{
    .strain_constant = 12.5, .stress_constant = 2000.0, .convention = "test"};

RheometerCurve curve(const std::string& csv) {
  return read_rheometer_curves(CsvTable::parse(csv, "data.csv"), {})[0];
}

TEST(MeasuredTorques, DerivesAngularVelocityAndTorqueFromRateAndStress) {
  const auto m = measured_torques(
      curve("Shear rate [1/s],Stress [Pa]\n12.5,4000\n25,5000\n50,6000\n100,8000\n"), kConstants,
      0.0, 1e9);
  ASSERT_EQ(m.angular_velocity.size(), 4u);
  EXPECT_DOUBLE_EQ(m.angular_velocity[0], 1.0);  // 12.5 1/s / 12.5 1/rad
  EXPECT_DOUBLE_EQ(m.torque[0], 2.0);            // 4000 Pa / 2000 Pa/(N m)
  EXPECT_DOUBLE_EQ(m.stress[3], 8000.0);
  EXPECT_EQ(m.conversions.size(), 2u) << "both Omega and M are derived, and said so";
  EXPECT_DOUBLE_EQ(m.stress_per_torque, 2000.0) << "c_τ: the torques are derived with it";
  EXPECT_FALSE(m.normal_force.has_value());
}

TEST(MeasuredTorques, KeepsMeasuredTorquesAndDerivesOnlyWhatIsMissing) {
  // The castor-oil export: the rate is the instrument's, the torque is measured.
  const auto m =
      measured_torques(curve("Shear rate [1/s],Stress [Pa],Torque [mN.m],Axial force [g]\n"
                             "25,5000,7,1\n12.5,4000,3,2\n50,6000,9,3\n100,8000,11,4\n"),
                       kConstants, 0.0, 1e9);
  EXPECT_DOUBLE_EQ(m.angular_velocity[0], 1.0);
  EXPECT_DOUBLE_EQ(m.torque[0], 3e-3) << "the measured torque, not stress / constant";
  ASSERT_TRUE(m.normal_force.has_value());
  EXPECT_DOUBLE_EQ((*m.normal_force)[0], 2.0 * 9.80665e-3);
  // Stress and torque both measured: the file's own stress per torque, the
  // median of the ratios (7.27e5 of 6.67e5, 7.14e5, 7.27e5, 1.33e6 Pa/(N m)),
  // converts predicted torques, and differing from c_τ it is said.
  EXPECT_DOUBLE_EQ(m.stress_per_torque, 8000.0 / 11e-3);
  ASSERT_EQ(m.conversions.size(), 2u);
  EXPECT_NE(m.conversions[1].find("the file's own stress per torque"), std::string::npos);
}

TEST(MeasuredTorques, AppliesTheRateWindowAndRefusesTooFewPoints) {
  const std::string data = "Angular velocity [rad/s],Torque [N.m]\n1,1\n2,2\n4,3\n8,4\n";
  // Rates are c_gamma Omega = 12.5, 25, 50, 100 1/s.
  const auto m = measured_torques(curve(data), kConstants, 20.0, 60.0);
  EXPECT_EQ(m.angular_velocity, (std::vector<double>{2.0, 4.0}));
  EXPECT_EQ(m.left_out, 2u);
  EXPECT_THROW(measured_torques(curve(data), kConstants, 20.0, 30.0), InputError);
}

}  // namespace
}  // namespace softglass::macro::app
