// Fuzzing the reader of measured rheometer data (common/measured_file.h,
// common/measured_curves.h) with mutated instrument exports, in every export
// format and both layouts, each read with and without units from the command
// line. Accepted curves are fitted or compared: every value finite, rates and
// stresses positive, at least 4 points.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <sstream>

#include "common/measured_curves.h"
#include "common/measured_file.h"
#include "fuzz_check.h"

namespace softglass::bridge {
namespace {

using namespace softglass::testing::fuzz;

const std::string kInstrument =
    "Stress [Pa],Shear rate [1/s],Viscosity [Pa.s],N1 [kPa]\n"
    "260.59,1000.0,0.26,0.28\n20.0,1.0,20.0,0.27\n78.1,100.0,0.78,0.27\n33.6,10.0,3.36,0.27\n";
const std::string kSamples =
    "sample_id,shear_rate_1/s,stress_MPa,N1 [mPa]\n"
    "A,1,0.010,1\nB,1,0.020,2\nA,2,0.011,1\nB,2,0.021,2\nA,3,0.012,1\nB,3,0.022,2\n"
    "A,4,0.013,1\nB,4,0.023,2\n";
const std::string kPaired =
    "0.68,,0.80,\n0.001,4.7,0.001,28.7\n0.01,4.9,0.01,29.7\n0.1,5.5,0.1,34.0\n1,7.2,1,42.4\n"
    ",,10,63.2\n";
const std::string kTorques =
    "Angular velocity [rpm],Torque [mN.m],Axial force [g],Temperature [C]\n"
    "60,3,-1,25\n30,2,0.5,25\n90,4,2,25\n120,5,3,25\n";

// Exports in the vendors' layouts (tests/data/instrument_exports/), as UTF-8.
std::string export_text(const std::string& name) {
  std::ifstream in(std::string(SOFTGLASS_SOURCE_DIR) + "/tests/data/instrument_exports/" + name);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}
const std::string kTrios = export_text("trios_text_export.txt");
const std::string kTriosLims = export_text("trios_lims_export.txt");
const std::string kRheoCompass = export_text("rheocompass_comma_utf8_bom.csv");
const std::string kSpreadsheet = export_text("spreadsheet_european.csv");
const std::string kUnitsRow = export_text("units_row_tab.txt");

const MeasuredReading kNoUnits{}, kUnits{.rate = "1/min", .stress = "kPa"};

// Reads `text` with the command line's units and without; returns whether the
// first was accepted (every seed is, with them).
template <class Read, class Check>
bool read_both_ways(const std::string& text, const std::string& input, Read read, Check check) {
  std::optional<MeasuredFile> file;
  if (!accepted([&] { file = parse_measured_file(text, "m.csv"); }, input)) return false;
  bool with_units = false;
  for (const MeasuredReading* units : {&kUnits, &kNoUnits}) {
    const bool ok = read_and_check([&] { return read(*file, *units); }, check, input);
    if (units == &kUnits) with_units = ok;
  }
  return with_units;
}

TEST(MeasuredCurvesFuzz, RefusesOrReadsEveryMutatedFlowCurve) {
  fuzz_text({kInstrument, kSamples, kPaired, kTrios, kTriosLims, kRheoCompass, kSpreadsheet,
             kUnitsRow},
            51, 4000, [](const std::string& text, const std::string& input) {
              const auto read = [](const MeasuredFile& file, const MeasuredReading& units) {
                return read_measured_curves(file, units);
              };
              return read_both_ways(text, input, read,
                                    [&](const std::vector<MeasuredCurve>& curves) {
                                      for (const MeasuredCurve& c : curves) {
                                        EXPECT_GE(c.shear_rate.size(), 4u) << input;
                                        EXPECT_EQ(c.stress.size(), c.shear_rate.size()) << input;
                                        for (const auto* values : {&c.shear_rate, &c.stress}) {
                                          expect_all_finite(*values, "a rate or stress", input);
                                          for (const double v : *values) EXPECT_GT(v, 0.0) << input;
                                        }
                                        if (c.N1) expect_all_finite(*c.N1, "N1", input);
                                      }
                                    });
            });
}

TEST(MeasuredCurvesFuzz, RefusesOrReadsEveryMutatedRheometerExport) {
  fuzz_text({kInstrument, kSamples, kPaired, kTorques, kTrios, kTriosLims, kRheoCompass,
             kSpreadsheet, kUnitsRow},
            52, 4000, [](const std::string& text, const std::string& input) {
              const auto read = [](const MeasuredFile& file, const MeasuredReading& units) {
                return read_rheometer_curves(file, units);
              };
              return read_both_ways(text, input, read,
                                    [&](const std::vector<RheometerCurve>& curves) {
                                      for (const RheometerCurve& c : curves) {
                                        EXPECT_GE(c.size(), 4u) << input;
                                        for (const auto& [quantity, values] : c.values) {
                                          EXPECT_EQ(values.size(), c.size()) << input;
                                          expect_all_finite(values, "a measured value", input);
                                        }
                                      }
                                    });
            });
}

}  // namespace
}  // namespace softglass::bridge
