// Reading measured flow curves: the rheometer layouts, units and their
// conversion, and the refusal of missing, reduced or mixed units and bad values.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>

#include "common/errors.h"
#include "common/measured/layout.h"
#include "common/measured_curves.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {

using testing::expect_contains;
using testing::refusal_of;

std::vector<MeasuredCurve> read(const std::string& text, MeasuredReading units = {}) {
  return read_measured_curves(CsvTable::parse(text, "data.csv"), units);
}

std::string refusal(const std::string& text, MeasuredReading units = {}) {
  try {
    read(text, units);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}


const std::string kInstrument =
    "Stress [Pa],Shear rate [1/s],Viscosity [Pa.s],Normal stress [Pa]\n"
    "260.59,1000.0,0.26,0.28\n"
    "20.0,1.0,20.0,0.27\n"
    "78.1,100.0,0.78,0.27\n"
    "33.6,10.0,3.36,0.27\n";

TEST(MeasuredCurves, ReadsAnInstrumentExportSortedByRate) {
  const auto curves = read(kInstrument);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].label, "data");
  EXPECT_EQ(curves[0].shear_rate, (std::vector<double>{1.0, 10.0, 100.0, 1000.0}));
  EXPECT_EQ(curves[0].stress, (std::vector<double>{20.0, 33.6, 78.1, 260.59}));
  EXPECT_FALSE(curves[0].N1) << "'Normal stress' is not N1 (meaningless in Couette)";
}

TEST(MeasuredCurves, GroupsRowsBySampleAndReadsUnitSuffixes) {
  const auto curves = read(
      "sample_id,shear_rate_1/s,stress_kPa,N1 [Pa]\n"
      "A,1,0.010,1\nB,1,0.020,2\nA,2,0.011,1\nB,2,0.021,2\nA,3,0.012,1\nB,3,0.022,2\n"
      "A,4,0.013,1\nB,4,0.023,2\n");
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[1].label, "B");
  EXPECT_DOUBLE_EQ(curves[1].stress[0], 20.0) << "kPa converted to Pa";
  ASSERT_TRUE(curves[1].N1);
  EXPECT_EQ((*curves[1].N1)[3], 2.0);
}

TEST(MeasuredCurves, ReadsPairedColumnsWithUnitsFromTheCommandLine) {
  const std::string text =
      "0.68,,0.80,\n0.001,4.7,0.001,28.7\n0.01,4.9,0.01,29.7\n0.1,5.5,0.1,34.0\n1,7.2,1,42.4\n"
      ",,10,63.2\n";
  const auto curves = read(text, {.rate = "1/min", .stress = "Pa"});
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].label, "0.68");
  EXPECT_EQ(curves[0].shear_rate.size(), 4u) << "a shorter curve ends at empty cells";
  EXPECT_EQ(curves[1].shear_rate.size(), 5u);
  EXPECT_DOUBLE_EQ(curves[1].shear_rate[4], 10.0 / 60.0);
  expect_contains(refusal(text), {"no units", "--rate-unit"});
}

TEST(MeasuredCurves, RefusesMissingReducedAndMixedUnits) {
  expect_contains(refusal("shear rate,stress [Pa]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"'shear rate'", "no units"});
  expect_contains(refusal("Shear rate [1/s],Stress [E*]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"'E*' is not a stress unit", "dimensional"});
  expect_contains(refusal("gamma dot [1],stress [Pa]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"'1' is not a shear-rate unit"});
  expect_contains(refusal("Shear rate [1/s],Stress [Pa],N1 [1]\n1,2,1\n2,3,1\n3,4,1\n4,5,1\n"),
                  {"'N1 [1]'", "not a stress unit"});
  expect_contains(refusal("Viscosity [Pa.s],Torque [uN.m]\n1,2\n"),
                  {"shear-rate, angular-velocity or strain-amplitude column"});
  expect_contains(refusal("Angular velocity [rad/s],Torque [uN.m]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"needs a shear-rate and a stress column"});
  expect_contains(refusal("Shear rate [1/s],Torque [N]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"'N' is not a torque unit"});
  expect_contains(refusal("rate [1/s],stress [Pa],Stress [kPa]\n1,2,3\n"), {"second column"});
}

// An amplitude sweep: strains in % or as fractions, moduli as stresses, the
// frequency in rad/s or Hz and one per curve; moduli and strain required.
TEST(AmplitudeSweeps, ReadsStrainModuliAndFrequency) {
  const std::string text =
      "Storage modulus [kPa],Loss modulus [Pa],Angular frequency [Hz],Oscillation strain [%],"
      "Oscillation stress [Pa]\n"
      "0.15,5,0.5,0.1,0.01\n0.14,6,0.5,0.01,0.02\n0.12,9,0.5,1,0.1\n0.08,30,0.5,10,2\n";
  const auto sweeps = read_amplitude_sweeps(CsvTable::parse(text, "sweep.csv"));
  ASSERT_EQ(sweeps.size(), 1u);
  const MeasuredAmplitudeSweep& s = sweeps[0];
  EXPECT_DOUBLE_EQ(s.strain.front(), 1e-4) << "sorted by strain, % as a fraction";
  EXPECT_DOUBLE_EQ(s.storage.front(), 140.0);
  EXPECT_DOUBLE_EQ(s.loss.back(), 30.0);
  ASSERT_TRUE(s.angular_frequency.has_value());
  EXPECT_DOUBLE_EQ(*s.angular_frequency, std::numbers::pi);
  expect_contains(
      refusal_of([] {
        read_amplitude_sweeps(CsvTable::parse(
            "Storage modulus [Pa],Oscillation strain [%]\n1,1\n2,2\n3,3\n4,4\n", "s.csv"));
      }),
      {"loss-modulus"});
  expect_contains(refusal_of([] {
                    read_amplitude_sweeps(CsvTable::parse(
                        "Storage modulus [Pa],Loss modulus [Pa],Oscillation strain [%],Angular "
                        "frequency [rad/s]\n1,1,1,1\n2,2,2,1\n3,3,3,2\n4,4,4,1\n",
                        "s.csv"));
                  }),
                  {"one frequency"});
  expect_contains(
      refusal_of([] {
        read_amplitude_sweeps(CsvTable::parse(
            "Storage modulus [Pa],Loss modulus [Pa],Oscillation strain [E*]\n1,1,1\n", "s.csv"));
      }),
      {"'E*' is not a strain unit"});
}

TEST(RheometerCurves, ReadsTorqueAngularVelocityAndForceInSIUnits) {
  // Rows out of order: every column follows the angular velocity's sort.
  const std::string text =
      "Angular velocity [rpm],Torque [\u00b5N\u00b7m],Axial force [g],Temperature [C]\n"
      "60,3,-1,25\n30,2,0.5,25\n90,4,2,25\n120,5,3,25\n";
  const auto curves = read_rheometer_curves(CsvTable::parse(text, "torques.csv"), {});
  ASSERT_EQ(curves.size(), 1u);
  const RheometerCurve& c = curves[0];
  EXPECT_FALSE(c.has(Measured::shear_rate));
  EXPECT_FALSE(c.has(Measured::stress));
  const double two_pi = 2.0 * std::numbers::pi;
  EXPECT_DOUBLE_EQ(c[Measured::angular_velocity][0], 30.0 * two_pi / 60.0);
  EXPECT_DOUBLE_EQ(c[Measured::torque][0], 2e-6);
  EXPECT_DOUBLE_EQ(c[Measured::normal_force][0], 0.5 * 9.80665e-3);
  EXPECT_DOUBLE_EQ(c[Measured::normal_force][1], -1.0 * 9.80665e-3) << "forces may be negative";
  for (const char* unit : {"mN.m", "mN m", "mNm", "mN*m"}) {
    const auto m = read_rheometer_curves(
        CsvTable::parse(fmt::format("rate [1/s],torque [{}]\n1,1\n2,2\n3,3\n4,4\n", unit), "t.csv"),
        {});
    EXPECT_DOUBLE_EQ(m[0][Measured::torque][3], 4e-3) << unit;
  }
}

// Issue 65, class B1: an amplitude sweep given where a flow curve is read
// reached a column it does not have and failed with "map::at". Each reader
// says what the file is instead; a curve asked for a quantity it lacks names
// it.
TEST(RheometerCurves, AFileOfTheOtherKindIsNamedForWhatItIs) {
  const std::string sweep =
      "Storage modulus [Pa],Loss modulus [Pa],Oscillation torque [uN.m],Oscillation strain [%],"
      "Axial force [g]\n146,4.7,0.9,0.01,58\n137,5.7,1.1,0.013,58\n130,6,1.5,0.1,58\n"
      "100,20,3,1,58\n";
  const std::vector<RheometerCurve> curves =
      read_rheometer_curves(CsvTable::parse(sweep, "sweep.csv"), {});
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curve_kind(curves[0]), CurveKind::amplitude_sweep);
  expect_contains(
      refusal_of([&] { require_curve_kind(curves, CurveKind::flow_curve, "sweep.csv", "advice"); }),
      {"'sweep.csv' is an amplitude sweep (strain amplitude and G′/G″ columns), not "
       "a flow curve",
       ": advice"});
  expect_contains(refusal_of([&] { (void)curves[0][Measured::angular_velocity]; }),
                  {"curve 'sweep' has no angular velocity column"});
  expect_contains(refusal(sweep), {"is an amplitude sweep", "not a flow curve"});
  expect_contains(
      refusal_of([] {
        read_amplitude_sweeps(
            CsvTable::parse("Shear rate [1/s],Stress [Pa]\n1,2\n2,3\n3,4\n4,5\n", "flow.csv"));
      }),
      {"'flow.csv' is a flow curve (shear rate or angular velocity, and stress or torque "
       "columns), not an amplitude sweep"});
  expect_contains(refusal("Shear rate [1/s],Storage modulus [Pa]\n1,2\n2,3\n3,4\n4,5\n"),
                  {"is neither a flow curve nor an amplitude sweep (its columns: shear rate, G′)"});
}

TEST(MeasuredCurves, RefusesBadValuesAndShortCurves) {
  expect_contains(refusal("rate [1/s],stress [Pa]\n1,2\n2,-3\n3,4\n4,5\n"),
                  {"line 3", "'stress [Pa]'", "must be > 0"});
  expect_contains(refusal("rate [1/s],stress [Pa]\n1,2\n2,nan\n3,4\n4,5\n"),
                  {"line 3", "not finite"});
  expect_contains(refusal("rate [1/s],stress [Pa]\n1,2\n2,3\n3,4\n"), {"3 point(s)", "at least 4"});
}

// The layouts are tried in their registry's order: a header of labelled
// column pairs is read as `paired`, any other as `long`, which takes them all.
TEST(MeasuredLayouts, TheFirstLayoutThatRecognisesAHeaderReadsIt) {
  const auto first = [](const std::vector<std::string>& header) {
    for (const auto& layout : measured::layouts().entries())
      if (layout.recognises(header)) return layout.name;
    return std::string("none");
  };
  EXPECT_EQ(first({"0.68", "", "0.70", ""}), "paired");
  EXPECT_EQ(first({"Shear rate [1/s]", "Stress [Pa]"}), "long");
  EXPECT_EQ(first({"0.68", "", "0.70"}), "long");  // an unpaired label
  EXPECT_EQ(first({"", "0.68"}), "long");
}

}  // namespace
}  // namespace softglass
