// `macro compare` from the outside. A "measurement" made from the exact
// finite-angle cone-plate solution (macro.md) in an instrument's units (rpm,
// mN.m, grams of axial force) must come back with relative errors at the
// finite-element scene's accuracy; bad requests give exit code 2 naming the
// problem, existing results exit code 3.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "common/csv_table.h"
#include "common/h5_file.h"
#include "macro/exact/cone_plate.h"
#include "tests/common/command_line.h"
#include "tests/common/test_files.h"

namespace softglass::macro {
namespace {

namespace fs = std::filesystem;
using softglass::testing::read_text;
using softglass::testing::TemporaryDirectory;
using softglass::testing::write_text;

constexpr double kRadius = 0.025, kAngleDeg = 2.0;
const HerschelBulkley kLaw{.yield_stress = 10.0, .consistency = 5.0, .flow_index = 0.5};
const NormalStressLaw kN1{.yield = 2.0, .consistency = 3.0, .flow_index = 0.5};

std::string material_text(double tau_y) {
  return fmt::format(
      "subsection material\n set model = herschel-bulkley\n set yield stress = {}\n"
      " set consistency = {}\n set flow index = {}\n set N1 yield = {}\n"
      " set N1 consistency = {}\n set N1 flow index = {}\nend\n",
      tau_y, kLaw.consistency, kLaw.flow_index, kN1.yield, kN1.consistency, kN1.flow_index);
}

class MacroCompare : public ::testing::Test {
 protected:
  void SetUp() override {
    // The ideal cone: truncation 1e-7 of the radius (its effect ~1e-21).
    write_text(dir_.path() / "cone.prm",
               fmt::format("set scene = cone-plate\ninclude material.prm\n"
                           "subsection cone-plate\n set radius = {}\n set angle = {}\n"
                           " set truncation = 2.5e-9\nend\n",
                           kRadius, kAngleDeg));
    write_text(dir_.path() / "material.prm", material_text(kLaw.yield_stress));
    // The measurement: exact torque and normal force at 6 speeds over 3.5
    // decades, in the units of a rheometer export.
    const exact::ConePlate cone{.radius = kRadius, .angle = kAngleDeg * std::numbers::pi / 180};
    std::ostringstream data;
    data << "Angular velocity [rpm],Torque [mN.m],Axial force [g],Temperature [C]\n";
    for (double omega : {0.003, 0.03, 0.3, 1.0, 3.0, 10.0}) {
      data << fmt::format("{:.12g},{:.12g},{:.12g},25\n", omega * 60 / (2 * std::numbers::pi),
                          1e3 * exact::torque(kLaw, cone, omega),
                          exact::normal_force(*normal_stress_curve(kN1), cone, omega) / 9.80665e-3);
    }
    write_text(dir_.path() / "measured.csv", data.str());
  }

  softglass::testing::Outcome compare(const std::string& arguments) {
    return softglass::testing::run_tool(MACRO_EXECUTABLE, "compare " + arguments, dir_.path(),
                                        dir_.path() / "capture");
  }

  // Column `name` of out/comparison.csv.
  std::vector<double> column(const std::string& name) {
    const fs::path file = dir_.path() / "out" / "comparison.csv";
    const CsvTable csv = CsvTable::parse(read_text(file), file.string());
    std::vector<double> values;
    for (std::size_t c = 0; c < csv.columns(); ++c) {
      if (split_units(csv.header()[c]).name != name) continue;
      for (std::size_t r = 0; r < csv.rows(); ++r) values.push_back(csv.number(r, c));
      return values;
    }
    ADD_FAILURE() << "no column " << name;
    return values;
  }

  TemporaryDirectory dir_;
};

TEST_F(MacroCompare, RecoversTheExactConePlateTorquesAndNormalForces) {
  const auto o = compare("cone.prm measured.csv -o out -q");
  ASSERT_EQ(o.code, 0) << o.err;
  const auto torque_error = column("relative_error");
  ASSERT_EQ(torque_error.size(), 6u);
  // The standard preset's requirement on exact references (docs/macro.md).
  for (double e : torque_error) EXPECT_LT(std::abs(e), 1e-3);
  // The normal force integrates N1(γ̇)/2 over the plate; the exact value takes
  // the small-angle uniform rate, which the finite angle changes by O(β²) ~ 1e-3.
  for (double e : column("normal_force_relative_error")) EXPECT_LT(std::abs(e), 5e-3);
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "summary.txt"));
  // comparison.h5 holds the same table (the CSV prints 8 significant digits).
  const softglass::H5Group h5 =
      softglass::H5File::open(dir_.path() / "out" / "comparison.h5").root();
  const std::vector<double> stored = h5.read_array("results/relative_error").data;
  ASSERT_EQ(stored.size(), torque_error.size());
  for (std::size_t k = 0; k < stored.size(); ++k)
    EXPECT_NEAR(stored[k], torque_error[k], 1e-7 * std::max(std::abs(stored[k]), 1e-3));
  EXPECT_EQ(h5.dataset_attribute("results/measured_torque", "units"), "N m");
}

TEST_F(MacroCompare, MaterialOptionReplacesTheScenesMaterial) {
  // Twice the yield stress: the measured (τ_y = 10 Pa) torques are now too low.
  write_text(dir_.path() / "stiffer.prm", material_text(2.0 * kLaw.yield_stress));
  const auto o = compare("cone.prm measured.csv -o out -q --material stiffer.prm");
  ASSERT_EQ(o.code, 0) << o.err;
  for (double e : column("relative_error")) EXPECT_GT(e, 0.05);
  EXPECT_NE(read_text(dir_.path() / "out" / "summary.txt").find("tau_y = 20 Pa"),
            std::string::npos);
}

TEST_F(MacroCompare, RefusesBadRequests) {
  write_text(dir_.path() / "channel.prm",
             "set scene = channel\ninclude material.prm\nsubsection channel\n set half height = "
             "0.005\nend\n");
  write_text(dir_.path() / "two.csv",
             "sample,Angular velocity [rad/s],Torque [N.m]\na,1,1\na,2,2\na,3,3\na,4,4\n"
             "b,1,1\nb,2,2\nb,3,3\nb,4,4\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"channel.prm measured.csv -o out -q", "has no rheometer torque"},
      {"cone.prm two.csv -o out -q", "choose one with --sample"},
      {"cone.prm two.csv -o out -q --sample c", "--sample c: no such curve"},
      {"cone.prm missing.csv -o out -q", "missing.csv"},
      {"cone.prm measured.csv -o out -q --strain-constant -3", "--strain-constant = -3"},
      {"cone.prm measured.csv -o out -q --min-rate 1e6", "at least 2"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto o = compare(arguments);
    EXPECT_EQ(o.code, 2) << arguments;
    EXPECT_NE(o.err.find(message), std::string::npos) << arguments << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(dir_.path() / "out" / "comparison.csv")) << "nothing half-written";
}

// Issue 19, class 3: a measured angular velocity whose shear-rate scale
// overflows is bad input naming the data file, not a failed solve.
TEST_F(MacroCompare, AbsurdMeasuredSpeedIsBadInput) {
  write_text(dir_.path() / "absurd.csv",
             "Angular velocity [rad/s],Torque [N.m]\n0.1,1e-3\n1,2e-3\n10,4e-3\n1e300,8e-3\n");
  const auto o = compare("cone.prm absurd.csv -o out -q");
  EXPECT_EQ(o.code, 2) << o.err;
  for (const char* part :
       {"characteristic shear rate", "measurement/angular velocity = 1e+300", "absurd.csv"})
    EXPECT_NE(o.err.find(part), std::string::npos) << part << " in " << o.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

// Issue 19, class 8: a file with far more points than a flow curve is refused
// before any solve, naming --max-points, which compares an even selection.
TEST_F(MacroCompare, TooManyPointsAreRefusedOrThinned) {
  std::ostringstream data;
  data << "Angular velocity [rad/s],Torque [N.m]\n";
  const std::size_t rows = 10001;
  for (std::size_t i = 0; i < rows; ++i) {
    const double omega = std::pow(10.0, -2.0 + 3.0 * double(i) / double(rows - 1));
    data << fmt::format("{:.12g},{:.12g}\n", omega, 1e-3 * (1.0 + std::sqrt(omega)));
  }
  write_text(dir_.path() / "long.csv", data.str());
  const auto refused = compare("cone.prm long.csv -o out -q");
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("has 10001 points"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--max-points"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
  const auto thinned = compare("cone.prm long.csv -o out -q --max-points 3");
  ASSERT_EQ(thinned.code, 0) << thinned.err;
  const std::vector<double> omega = column("angular_velocity");
  ASSERT_EQ(omega.size(), 3u);
  EXPECT_NEAR(omega.front(), 0.01, 1e-9);
  EXPECT_NEAR(omega.back(), 10.0, 1e-8);
  EXPECT_NE(read_text(dir_.path() / "out" / "summary.txt").find("9998 left out by --max-points"),
            std::string::npos);
}

// Issue 19, class 5: on a full disk gnuplot exits with success and leaves a
// truncated PNG, which was put in place. Issue 65, class B4: it was then
// dropped with exit code 0 and blamed on gnuplot. A plot that cannot be
// stored is an error naming the file and the reason, and no result (nor its
// folder) is left. The disk is filled by a file-size limit (SIGXFSZ ignored,
// so that writes fail as on a full disk): the tables fit, the plot does not.
TEST_F(MacroCompare, TruncatedPlotIsNotPutInPlace) {
  if (!fs::exists("/usr/bin/gnuplot")) GTEST_SKIP() << "no gnuplot";
  const softglass::testing::Outcome o = softglass::testing::run_tool_on_full_disk(
      MACRO_EXECUTABLE, "compare cone.prm measured.csv -o out -q", dir_.path(),
      dir_.path() / "capture", 24);
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("macro: error: cannot write 'out/comparison.png': File too large"),
            std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
  // Without the limit the plot is complete.
  ASSERT_EQ(compare("cone.prm measured.csv -o out -q").code, 0);
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "comparison.png"));
}

// Without gnuplot the comparison is written without its plot, and says why.
TEST_F(MacroCompare, WithoutGnuplotTheResultHasNoPlotAndAWarning) {
  const softglass::testing::Outcome o =
      softglass::testing::run_tool("/usr/bin/env",
                                   "PATH=/nonexistent '" + std::string(MACRO_EXECUTABLE) +
                                       "' compare cone.prm measured.csv -o out -q",
                                   dir_.path(), dir_.path() / "capture");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.err.find("macro: warning: no plot written (gnuplot is not installed)"),
            std::string::npos)
      << o.err;
  EXPECT_EQ(
      softglass::testing::file_names(dir_.path() / "out"),
      (std::vector<std::string>{"comparison.csv", "comparison.h5", "manifest.txt", "summary.txt"}));
  EXPECT_NE(
      read_text(dir_.path() / "out" / "summary.txt").find("no plot: gnuplot is not installed"),
      std::string::npos);
}

// Issue 65, class B1: an amplitude sweep (G′, G″ over the strain amplitude)
// given as the measurement ended in "macro: error: map::at", exit code 1.
TEST_F(MacroCompare, AnAmplitudeSweepIsRefusedForWhatItIs) {
  write_text(dir_.path() / "sweep.csv",
             "Storage modulus [Pa],Loss modulus [Pa],Oscillation strain [%],Axial force [g]\n"
             "146,4.7,0.01,58\n137,5.7,0.013,58\n130,6,0.1,58\n100,20,1,58\n");
  const auto o = compare("cone.prm sweep.csv -o out -q");
  EXPECT_EQ(o.code, 2) << o.err;
  for (const char* part :
       {"'sweep.csv' is an amplitude sweep (strain amplitude and G′/G″ columns), not a flow curve",
        "bridge amplitude-sweep"})
    EXPECT_NE(o.err.find(part), std::string::npos) << part << " in " << o.err;
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
}

// Issue 65, class B2: as for `macro run` (cli_test.cpp).
TEST_F(MacroCompare, AnOutputFolderThatIsAFileIsBadInput) {
  write_text(dir_.path() / "taken", "mine");
  const auto o = compare("cone.prm measured.csv -o taken -q");
  EXPECT_EQ(o.code, 2) << o.err;
  EXPECT_NE(o.err.find("output folder 'taken' is a file, not a folder"), std::string::npos)
      << o.err;
  EXPECT_EQ(read_text(dir_.path() / "taken"), "mine");
}

TEST_F(MacroCompare, ExistingResultsNeedForce) {
  ASSERT_EQ(compare("cone.prm measured.csv -o out -q").code, 0);
  EXPECT_EQ(compare("cone.prm measured.csv -o out -q").code, 3);
  EXPECT_EQ(compare("cone.prm measured.csv -o out -q --force").code, 0);
}

}  // namespace
}  // namespace softglass::macro

namespace softglass::macro {
namespace {

// The numbers of FOLDER/comparison.csv, row by row.
std::vector<std::vector<double>> comparison_rows(const fs::path& folder) {
  const CsvTable csv = CsvTable::parse(read_text(folder / "comparison.csv"), "comparison.csv");
  std::vector<std::vector<double>> rows(csv.rows());
  for (std::size_t r = 0; r < csv.rows(); ++r)
    for (std::size_t c = 0; c < csv.columns(); ++c) rows[r].push_back(csv.number(r, c));
  return rows;
}

// The castor-oil export of ../shared/data/rheometry/ (TA HR-3, DIN cylinders
// R1 = 14 mm, R2 = 15.2 mm, L = 42 mm) states the instrument's own constants:
// strain constant 12.1872 1/rad and stress constant 16243.3 Pa/(N m), the
// latter with an end-effect factor 1.1. The Couette scene's ISO 3219
// constants, computed from the geometry alone, must reproduce both.
TEST(MacroCompareRealData, CouetteConstantsAreTheInstrumentsOwn) {
  const fs::path data =
      fs::path(SOFTGLASS_SHARED_DIR) / "data" / "rheometry" / "castoroil85_couette_flow_sweep.csv";
  if (!fs::exists(data)) GTEST_SKIP() << data << " is absent";
  TemporaryDirectory dir;
  write_text(dir.path() / "material.prm", material_text(10.0));
  write_text(dir.path() / "cell.prm",
             "set scene = couette\ninclude material.prm\nsubsection couette\n"
             " set inner radius = 0.014\n set outer radius = 0.0152\n set length = 0.042\n"
             "end\nsubsection solver\n set preset = fast\nend\n");
  const auto o = softglass::testing::run_tool(
      MACRO_EXECUTABLE,
      fmt::format("compare cell.prm '{}' -o out -q --min-rate 300", data.string()), dir.path(),
      dir.path() / "capture");
  ASSERT_EQ(o.code, 0) << o.err;
  int rows = 0;
  for (const std::vector<double>& v : comparison_rows(dir.path() / "out")) {
    // Columns: Omega, rate, measured M, predicted M, error, estimate, measured τ, predicted τ.
    EXPECT_NEAR(v[1] / v[0], 12.1872, 12.1872 * 1e-5) << "Omega = rate / strain constant";
    EXPECT_NEAR(v[6] / v[2], 16243.3, 16243.3 * 2e-4) << "the export's stress per torque";
    EXPECT_NEAR((v[7] / v[3]) / (v[6] / v[2]), 1.0, 2e-4)
        << "both stresses with the export's own stress per torque";
    ++rows;
  }
  EXPECT_EQ(rows, 6) << "316 ... 1000 1/s";
  // The scene's ISO 3219 constant is 1.1 x the instrument's (its end-effect correction).
  EXPECT_NE(
      read_text(dir.path() / "out" / "summary.txt").find("the file's own stress per torque (below"),
      std::string::npos);
}

// The castor-oil flow sweep as TRIOS exports it (tab-separated, parameter
// blocks with the geometry's constants, a units row under the names, a peak
// hold before the sweep): `macro compare` must read the same points as from
// the plain CSV and say what it left out. It converts with the constants the
// export records (Ω = γ̇/12.1872, the scene's ISO constant is 12.18715...),
// so the speeds and predicted torques agree to the constants' 6 digits, and
// the predicted stress is the predicted torque times the export's stress
// constant, as the measured one is (the scene's ISO 3219 constant is 1.1 ×
// the instrument's end-effect corrected one).
TEST(MacroCompareRealData, ATriosExportComparesAsItsPlainCsv) {
  const fs::path data =
      fs::path(SOFTGLASS_SHARED_DIR) / "data" / "rheometry" / "castoroil85_couette_flow_sweep.csv";
  if (!fs::exists(data)) GTEST_SKIP() << data << " is absent";
  TemporaryDirectory dir;
  std::istringstream export_lines(read_text(data));
  std::string header, names, units, points;
  std::getline(export_lines, header);
  if (header.ends_with('\r')) header.pop_back();
  std::istringstream cells(header);
  for (std::string cell; std::getline(cells, cell, ',');) {
    const auto open = cell.rfind(" [");
    names += (names.empty() ? "" : "\t") + cell.substr(0, open);
    units += (units.empty() ? "" : "\t") + cell.substr(open + 2, cell.size() - open - 3);
  }
  for (std::string line; std::getline(export_lines, line);) {
    std::replace(line.begin(), line.end(), ',', '\t');
    points += line + "\n";
  }
  write_text(dir.path() / "trios.txt",
             "Filename\tcastoroil85\nInstrument name\tHR-3\n[Geometry Parameters]\n"
             "Geometry Type\tConcentric cylinders\nName\tDIN cylinders\n"
             "[Geometry Extended Parameters]\nStress constant\t16243.3 Pa/N.m\n"
             "Strain constant\t12.1872 1/rad\n[step]\nPeak hold - 1\nStress\tShear rate\n"
             "Pa\t1/s\n20\t1\n21\t1\n22\t1\n23\t1\n\n[step]\nFlow sweep - 2\n" +
                 names + "\n" + units + "\n" + points);
  write_text(dir.path() / "material.prm", material_text(10.0));
  write_text(dir.path() / "cell.prm",
             "set scene = couette\ninclude material.prm\nsubsection couette\n"
             " set inner radius = 0.014\n set outer radius = 0.0152\n set length = 0.042\n"
             "end\nsubsection solver\n set preset = fast\nend\n");
  for (const auto& [file, folder] : {std::pair{data.string(), "plain"}, {"trios.txt", "trios"}}) {
    const auto o = softglass::testing::run_tool(
        MACRO_EXECUTABLE,
        fmt::format("compare cell.prm '{}' -o {} -q --min-rate 300", file, folder), dir.path(),
        dir.path() / "capture");
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err.find("warning"), std::string::npos)
        << "the cell is the instrument's: " << o.err;
  }
  const auto trios = comparison_rows(dir.path() / "trios");
  const auto plain = comparison_rows(dir.path() / "plain");
  ASSERT_EQ(trios.size(), 6u);
  ASSERT_EQ(trios.size(), plain.size());
  for (std::size_t i = 0; i < trios.size(); ++i) {
    // Columns: Omega, rate, measured M, predicted M, error, estimate, measured τ, predicted τ.
    for (const std::size_t c : {1, 2, 6}) EXPECT_EQ(trios[i][c], plain[i][c]) << "row " << i;
    for (const std::size_t c : {0, 3}) EXPECT_NEAR(trios[i][c], plain[i][c], 1e-5 * plain[i][c]);
    // The export's stress and torque are each rounded to 6 digits.
    const double torque_ratio = trios[i][3] / trios[i][2];
    EXPECT_NEAR(trios[i][7] / trios[i][6], torque_ratio, 1e-5 * torque_ratio) << "row " << i;
  }
  EXPECT_NE(read_text(dir.path() / "trios" / "summary.txt")
                .find("measured file: step 'Peak hold - 1' left out"),
            std::string::npos);
}

// Issue 65, class B1, with the file of the report: the castor-oil amplitude
// sweep against the project's Couette cell was "map::at", exit code 1.
TEST(MacroCompareRealData, TheAmplitudeSweepExportIsRefusedForWhatItIs) {
  const fs::path data = fs::path(SOFTGLASS_SHARED_DIR) / "data" / "rheometry" /
                        "castoroil85_couette_amplitude_sweep.csv";
  if (!fs::exists(data)) GTEST_SKIP() << data << " is absent";
  TemporaryDirectory dir;
  const auto o = softglass::testing::run_tool(
      MACRO_EXECUTABLE,
      fmt::format("compare '{}/cases/castoroil_couette.prm' '{}' -o out -q", SOFTGLASS_SOURCE_DIR,
                  data.string()),
      dir.path(), dir.path() / "capture");
  EXPECT_EQ(o.code, 2) << o.err;
  EXPECT_NE(o.err.find("is an amplitude sweep (strain amplitude and G′/G″ columns), not a flow "
                       "curve"),
            std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace softglass::macro
