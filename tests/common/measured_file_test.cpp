// Instrument exports as users have them (tests/data/instrument_exports/,
// each written in its vendor's documented layout): every one reads to the
// same values as the plain CSV of the same curve, and malformed exports are
// refused with a message naming the cause.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/errors.h"
#include "common/measured_curves.h"
#include "common/measured_file.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {

using testing::expect_contains;
using testing::refusal_of;

const std::filesystem::path kExports =
    std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "tests/data/instrument_exports";

// The flow curve of `name`, every recognised column, its only one.
RheometerCurve flow_curve(const std::string& name) {
  const MeasuredFile file = read_measured_file(kExports / name);
  const auto curves = curves_of_kind(file, {}, CurveKind::flow_curve);
  EXPECT_EQ(curves.size(), 1u) << name;
  return curves.at(0);
}

MeasuredAmplitudeSweep amplitude_sweep(const std::string& name) {
  const auto sweeps = read_amplitude_sweeps(read_measured_file(kExports / name));
  EXPECT_EQ(sweeps.size(), 1u) << name;
  return sweeps.at(0);
}

// Equal to the last bits a unit factor's product may change (mN·m → N m is a
// multiplication by 1e-3; µN.m by 1e-6; rpm by 2π/60 of a 15-digit value).
void expect_same(const std::vector<double>& got, const std::vector<double>& want,
                 const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_NEAR(got[i], want[i], 1e-13 * std::abs(want[i])) << what << ", point " << i;
}

struct ExportCase {
  std::string file, format;
  std::size_t flow_columns;  // of shear rate, stress, torque, angular velocity
  bool has_amplitude_sweep;
};

class InstrumentExport : public ::testing::TestWithParam<ExportCase> {};

TEST_P(InstrumentExport, ReadsTheSameValuesAsThePlainCsv) {
  const ExportCase& c = GetParam();
  EXPECT_EQ(read_measured_file(kExports / c.file).format, c.format);
  const RheometerCurve want = flow_curve("plain_flow.csv"), got = flow_curve(c.file);
  for (const auto& [quantity, values] : want.values) {
    if (!got.has(quantity)) continue;  // not every export carries every column
    expect_same(got[quantity], values, c.file + ", " + quantity_name(quantity));
  }
  EXPECT_TRUE(got.has(Measured::shear_rate) && got.has(Measured::stress)) << c.file;
  EXPECT_EQ(got.values.size(), c.flow_columns) << c.file;
  if (!c.has_amplitude_sweep) return;
  const MeasuredAmplitudeSweep a = amplitude_sweep("plain_amplitude.csv"),
                               b = amplitude_sweep(c.file);
  expect_same(b.strain, a.strain, c.file + ", strain amplitude");
  expect_same(b.storage, a.storage, c.file + ", G'");
  expect_same(b.loss, a.loss, c.file + ", G''");
  ASSERT_TRUE(b.angular_frequency.has_value()) << c.file;
  EXPECT_DOUBLE_EQ(*b.angular_frequency, *a.angular_frequency) << c.file;
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, InstrumentExport,
    ::testing::Values(ExportCase{"trios_text_export.txt", "trios", 4, true},
                      ExportCase{"trios_csv_export.csv", "trios", 4, true},
                      ExportCase{"trios_lims_export.txt", "trios", 3, true},
                      ExportCase{"rheocompass_semicolon_decimal_comma_utf16.csv", "rheocompass", 4,
                                 true},
                      ExportCase{"rheocompass_comma_utf8_bom.csv", "rheocompass", 4, true},
                      ExportCase{"rheocompass_tab_decimal_comma.txt", "rheocompass", 4, true},
                      ExportCase{"spreadsheet_european.csv", "delimited", 4, false},
                      ExportCase{"units_row_tab.txt", "delimited", 4, false},
                      ExportCase{"plain_flow.csv", "plain", 4, false}),
    [](const auto& test) {
      std::string name = test.param.file;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(InstrumentExport, TriosRecordsItsGeometryAndConstants) {
  const MeasuredFile file = read_measured_file(kExports / "trios_text_export.txt");
  EXPECT_EQ(file.instrument.geometry, "40 mm 2° steel cone (Cone)");
  ASSERT_TRUE(file.instrument.stress_constant && file.instrument.strain_constant);
  EXPECT_DOUBLE_EQ(*file.instrument.stress_constant, 59683.1);
  EXPECT_DOUBLE_EQ(*file.instrument.strain_constant, 28.6479);
  ASSERT_EQ(file.notes.size(), 1u);
  expect_contains(file.notes[0], {"'Peak hold - 1' left out: a peak hold is not a steady flow"});
  EXPECT_EQ(flow_curve("trios_text_export.txt").label, "Flow sweep - 2");
}

TEST(InstrumentExport, AFormatChosenByHandMustFitTheFile) {
  expect_contains(
      refusal_of([] { read_measured_file(kExports / "trios_text_export.txt", "rheocompass"); }),
      {"--format rheocompass reads", "it looks like trios"});
  expect_contains(refusal_of([] { read_measured_file(kExports / "plain_flow.csv", "excel"); }),
                  {"measured-file format 'excel' is unknown", "trios, rheocompass, plain"});
  EXPECT_EQ(read_measured_file(kExports / "plain_flow.csv", "delimited").format, "delimited");
}

// Malformed exports, each with the cause its message must name.
TEST(InstrumentExport, MalformedExportsAreRefusedNamingTheCause) {
  const auto refused = [](const std::string& text, const std::string& source = "bad.txt") {
    return refusal_of([&] {
      const MeasuredFile file = parse_measured_file(text, source);
      read_measured_curves(file, {});
    });
  };
  // A TRIOS step whose units row is missing: the points follow the names.
  expect_contains(
      refused("Filename\tx\n[step]\nFlow sweep - 1\nStress\tShear rate\n"
              "1.0\t0.1\n2.0\t1.0\n3.0\t10\n4.0\t100\n"),
      {"line 5", "the row under the column names should hold their units", "the number '1.0'"});
  // A TRIOS export of transients only.
  expect_contains(
      refused("[step]\nPeak hold - 1\nStress\tShear rate\nPa\t1/s\n1\t2\n"),
      {"no step is a steady flow curve or an amplitude sweep", "'Peak hold - 1' left out"});
  // A thousands separator in a decimal-comma file.
  expect_contains(refused("Shear rate [1/s];Stress [Pa]\n0,1;1.234,5\n1;2\n10;3\n100;4\n"),
                  {"line 2", "'1.234,5' is written with a thousands separator"});
  // Decimal commas and points in one file.
  expect_contains(refused("Shear rate [1/s];Stress [Pa]\n0,1;1\n1;2.5\n10;3\n100;4\n"),
                  {"decimal commas (line 2) and with decimal points (line 3)"});
  // A RheoCompass interval without its row of units.
  expect_contains(refused("Result:;r\nInterval data:;Shear Rate;Shear Stress\n;0,1;1\n;1;2\n"),
                  {"RheoCompass", "line 2", "no row of bracketed units"});
  // A unit no column knows, in a units row.
  expect_contains(refused("Shear rate\tStress\n[1/s]\t[psi]\n0.1\t1\n1\t2\n10\t3\n100\t4\n"),
                  {"'psi' is not a stress unit"});
  // Numbers without names above them.
  expect_contains(refused("0.1;1\n1;2\n"), {"the numbers have no row of column names"});
}

TEST(InstrumentExport, AnExportOfOneKindIsNotReadAsAnother) {
  // The TRIOS export holds a flow sweep and an amplitude sweep: each reader
  // takes its own, and a file of only the other kind is refused naming it.
  const std::string amplitude_only =
      "[step]\nAmplitude sweep - 1\nOscillation strain\tStorage modulus\tLoss modulus\n%\tPa\tPa\n"
      "0.1\t100\t5\n1\t99\t6\n10\t60\t30\n100\t10\t20\n[step]\nFlow sweep - 2\nStress\tShear "
      "rate\nPa\t1/s\n10\t0.1\n11\t0.1\n12\t0.1\n13\t0.1\n";
  expect_contains(
      refusal_of([&] { read_measured_curves(parse_measured_file(amplitude_only, "a.txt"), {}); }),
      {"no section that is a flow curve", "'Amplitude sweep - 1' (an amplitude sweep",
       "'Flow sweep - 2' (a flow curve at one rate)"});
}

}  // namespace
}  // namespace softglass
