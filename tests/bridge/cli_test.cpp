// The `bridge` command line, driven as a user would: exit codes (0 ok, 2 bad
// input, 3 output exists), messages that name the problem, result files that
// appear whole or not at all, and the three subcommands end to end on a
// synthetic sweep.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <sstream>
#include <vector>

#include "bridge_test_support.h"
#include "synthetic_sweep.h"
#include "tests/common/command_line.h"

namespace softglass::bridge {
namespace {

namespace fs = std::filesystem;
using testing::expect_contains;

using softglass::testing::Outcome;

class BridgeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(work());
    const testing::SyntheticSweep s = testing::make_synthetic_sweep({}, 1);
    testing::write_text(work() / "sweep.csv", testing::table_csv(s));
    testing::write_text(work() / "runs.csv", testing::runs_csv(s));
  }

  fs::path work() const { return dir_ / "work"; }

  Outcome bridge(const std::string& arguments) const {
    return softglass::testing::run_tool(SOFTGLASS_BRIDGE_EXECUTABLE, arguments, work(),
                                        dir_ / "capture");
  }

  std::vector<std::string> files() const { return softglass::testing::file_names(work()); }

  testing::TemporaryDirectory dir_;
};

const char* kFit = "fit sweep.csv --packings runs.csv --bootstrap 100 --quiet";

TEST_F(BridgeCli, HelpAndBadCommandLines) {
  const Outcome help = bridge("--help");
  EXPECT_EQ(help.code, 0);
  expect_contains(help.out, {"fit", "material", "rescale"});
  EXPECT_EQ(bridge("").code, 2) << "a subcommand is required";
  EXPECT_EQ(bridge("fit").code, 2) << "fit needs a table";
  EXPECT_EQ(bridge("fit sweep.csv --bootstrap 1").code, 2);
  EXPECT_EQ(bridge("material law.prm --phi 0.8 --viscosity 1e-3").code, 2) << "no E*";
  EXPECT_EQ(bridge("material law.prm --phi 0.8 --modulus 4e4 --interfacial-tension 5e-3 "
                   "--radius 1e-6 --viscosity 1e-3")
                .code,
            2)
      << "E* twice";
  EXPECT_EQ(
      bridge("rescale data.csv --viscosity 1e-3 --yield-strain 0.03 --shear-modulus 100").code, 2);
  EXPECT_EQ(bridge("rescale data.csv --viscosity 1e-3 --yield-strain 0.03 --modulus 4e4 "
                   "--shared-modulus")
                .code,
            2)
      << "E* both given and fitted";
}

TEST_F(BridgeCli, FitWritesTheLawAndItsTablesAndRefusesToOverwrite) {
  const Outcome o = bridge(kFit);
  ASSERT_EQ(o.code, 0) << o.err;
  expect_contains(o.out, {"k    sigma/sigma_y", "80 ± 3", "gamma_y", "written  law.prm"});
  EXPECT_EQ(files(), (std::vector<std::string>{"law.prm", "law_constants.csv", "law_phi.csv",
                                               "law_points.csv", "runs.csv", "sweep.csv"}));
  expect_contains(testing::read_text(work() / "law.prm"),
                  {"# command:", "--packings runs.csv", "packing bootstrap", "subsection law"});

  const std::string before = testing::read_text(work() / "law_phi.csv");
  const Outcome again = bridge(kFit);
  EXPECT_EQ(again.code, 3);
  expect_contains(again.err, {"law.prm", "--force"});
  EXPECT_EQ(testing::read_text(work() / "law_phi.csv"), before);
  EXPECT_EQ(bridge(std::string(kFit) + " --force").code, 0);
  EXPECT_EQ(files().size(), 6u) << "no temporary file left";
}

// The lines of a text but its `#` comments; for a CSV text and a non-empty
// `drop`, without the columns whose names start with `drop`.
std::string data_without(const std::string& text, const std::string& drop = "") {
  std::istringstream in(text);
  std::string line, out;
  std::vector<bool> keep;
  while (std::getline(in, line)) {
    if (line.starts_with("#")) continue;
    if (drop.empty()) {
      out += line + '\n';
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (keep.empty())
      for (const std::string& name : cells) keep.push_back(!name.starts_with(drop));
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (keep.at(c)) out += cells[c] + ',';
    out += '\n';
  }
  return out;
}

// A sweep's quasi-static rows (γ̃ = 0) leave every fitted number as it was
// without them, and their σ_y is reported beside the Herschel–Bulkley σ_y.
TEST_F(BridgeCli, FitLeavesQuasiStaticRowsOutAndReportsTheirYieldStress) {
  const testing::SyntheticTruth truth;
  const testing::SyntheticSweep s =
      testing::with_quasi_static(testing::make_synthetic_sweep(truth, 1), truth, 2);
  testing::write_text(work() / "aqs.csv", testing::table_csv(s));
  testing::write_text(work() / "aqs_runs.csv", testing::runs_csv(s));
  const Outcome plain = bridge(kFit);
  const Outcome aqs =
      bridge("fit aqs.csv --packings aqs_runs.csv --bootstrap 100 --quiet -o aqs.prm");
  ASSERT_EQ(plain.code, 0) << plain.err;
  ASSERT_EQ(aqs.code, 0) << aqs.err;
  EXPECT_EQ(plain.out.find("quasi-static"), std::string::npos) << plain.out;
  expect_contains(aqs.out, {"55 state points", "and 5 quasi-static (gamma~ = 0), not fitted",
                            "yield stress: quasi-static (AQS", "AQS sigma_y/E*", "diff/SE"});
  expect_contains(testing::read_text(work() / "aqs.prm"),
                  {"55 state points and 5 quasi-static (gamma~ = 0), not fitted"});
  for (const char* suffix : {".prm", "_points.csv", "_constants.csv"}) {
    EXPECT_EQ(data_without(testing::read_text(work() / (std::string("aqs") + suffix))),
              data_without(testing::read_text(work() / (std::string("law") + suffix))))
        << suffix;
  }
  const std::string phi = testing::read_text(work() / "aqs_phi.csv");
  expect_contains(softglass::testing::table_header(phi), {"sigma_yield_se [E*],sigma_yield_quasi_static "
                                               "[E*],sigma_yield_quasi_static_se [E*]"});
  EXPECT_EQ(data_without(phi, "sigma_yield_quasi_static"),
            data_without(testing::read_text(work() / "law_phi.csv"), "sigma_yield_quasi_static"));
}

// A fit over a window of rates is the fit of the table cut to that window,
// to the last digit (the quasi-static rows stay); a reversed window is refused.
TEST_F(BridgeCli, FitOverARateWindowIsTheFitOfTheTableCutToIt) {
  const testing::SyntheticTruth truth;
  testing::SyntheticSweep s =
      testing::with_quasi_static(testing::make_synthetic_sweep(truth, 1), truth, 2);
  testing::write_text(work() / "whole.csv", testing::table_csv(s));
  testing::write_text(work() / "whole_runs.csv", testing::runs_csv(s));
  const auto outside = [](double gamma_tilde) {
    return gamma_tilde > 0.0 && (gamma_tilde < 0.999999e-8 || gamma_tilde > 1.000001e-5);
  };
  std::erase_if(s.table.points, [&](const StatePoint& p) { return outside(p.gamma_tilde); });
  std::erase_if(s.runs, [&](const PackingRun& r) { return outside(r.gamma_tilde); });
  ASSERT_EQ(s.table.points.size(), 5u * (7u + 1u)) << "1e-8 … 1e-5 is 7 rates, plus AQS";
  testing::write_text(work() / "cut.csv", testing::table_csv(s));
  testing::write_text(work() / "cut_runs.csv", testing::runs_csv(s));

  const Outcome window = bridge(
      "fit whole.csv --packings whole_runs.csv --bootstrap 100 --quiet --min-rate 1e-8 "
      "--max-rate 1e-5 -o window.prm");
  const Outcome cut = bridge("fit cut.csv --packings cut_runs.csv --bootstrap 100 --quiet -o cut.prm");
  ASSERT_EQ(window.code, 0) << window.err;
  ASSERT_EQ(cut.code, 0) << cut.err;
  expect_contains(testing::read_text(work() / "window.prm"),
                  {"rates:    only gamma~ = 1e-08 ... 1e-05 fitted", "35 state points"});
  for (const char* suffix : {".prm", "_phi.csv", "_points.csv", "_constants.csv"}) {
    EXPECT_EQ(data_without(testing::read_text(work() / (std::string("window") + suffix))),
              data_without(testing::read_text(work() / (std::string("cut") + suffix))))
        << suffix;
  }

  const Outcome reversed =
      bridge("fit whole.csv --quiet --min-rate 1e-5 --max-rate 1e-8 -o reversed.prm");
  EXPECT_EQ(reversed.code, 2);
  expect_contains(reversed.err, {"rate window", "reversed"});
  EXPECT_FALSE(fs::exists(work() / "reversed.prm"));
}

TEST_F(BridgeCli, FitRefusesABadTableWithExitCodeTwo) {
  std::string text = testing::read_text(work() / "sweep.csv");
  text.replace(text.find("1.2868314229e-03"), 16, "nan");
  testing::write_text(work() / "bad.csv", text);
  const Outcome o = bridge("fit bad.csv --quiet");
  EXPECT_EQ(o.code, 2);
  expect_contains(o.err, {"bad.csv, line 3", "sigma [E*]", "not finite"});
  EXPECT_FALSE(fs::exists(work() / "law.prm"));
  EXPECT_EQ(bridge("fit no_such.csv --quiet").code, 2);
}

TEST_F(BridgeCli, MaterialForThePapersEmulsion) {
  ASSERT_EQ(bridge(kFit).code, 0);
  const Outcome printed = bridge("material law.prm --phi 0.80 --modulus 40e3 --viscosity 1e-3");
  ASSERT_EQ(printed.code, 0) << printed.err;
  expect_contains(printed.out,
                  {"# law:      law.prm", "phi = 0.8, E* = 40000 Pa, eta_s = 0.001 Pa s",
                   "subsection material", "set yield stress", "set N1 yield"});
  // E* = 9.92 γ_i/R: γ_i = 5 mN/m, R = 1.24 µm give 40 kPa.
  const Outcome emulsion = bridge(
      "material law.prm --phi 0.78 --interfacial-tension 5e-3 --radius 1.24e-6 --viscosity 1e-3 "
      "-o material.prm");
  ASSERT_EQ(emulsion.code, 0) << emulsion.err;
  expect_contains(emulsion.out, {"interpolated between", "written  material.prm"});
  expect_contains(testing::read_text(work() / "material.prm"),
                  {"9.92 gamma_i / R", "E* = 40000 Pa"});
  // Given the user's amplitude-sweep frequency, the crossover strain the flow
  // law implies, on screen and in the file, without a simulated sweep.
  const Outcome at_frequency = bridge(
      "material law.prm --phi 0.80 --modulus 40e3 --viscosity 1e-3 --frequency 1 -o m1.prm");
  ASSERT_EQ(at_frequency.code, 0) << at_frequency.err;
  expect_contains(at_frequency.out, {"crossover strain estimate at omega = 1 rad/s"});
  expect_contains(testing::read_text(work() / "m1.prm"),
                  {"# crossover strain estimate at omega = 1 rad/s", "omega~ = 2.5e-08"});

  const Outcome outside = bridge("material law.prm --phi 0.95 --modulus 40e3 --viscosity 1e-3");
  EXPECT_EQ(outside.code, 2);
  expect_contains(outside.err, {"outside the simulated range", "--extrapolate"});
  EXPECT_EQ(
      bridge("material law.prm --phi 0.92 --modulus 40e3 --viscosity 1e-3 --extrapolate").code, 0);
  EXPECT_EQ(bridge("material missing.prm --phi 0.8 --modulus 40e3 --viscosity 1e-3").code, 2);
}

// `bridge predict` on the bundled law: shear rate and stress first, the mode
// named, bad inputs refused with exit code 2 and no file; `material
// --tabulated` from the same law reads as a tabulated fragment.
TEST_F(BridgeCli, PredictWritesTheFlowCurveAndRefusesWhatFitsNoMode) {
  const std::string law = std::string(SOFTGLASS_SOURCE_DIR) + "/cases/bridge_law_paper_sweep.prm";
  const std::string base = "predict " + law + " --phi 0.85 --viscosity 0.89e-3 --rates 0.01,1,100";
  const Outcome b = bridge(base + " --plateau-modulus 143 -o predicted.csv");
  ASSERT_EQ(b.code, 0) << b.err;
  expect_contains(b.out, {"mode     (b) E* from the measured G'", "written  predicted.csv"});
  const std::string table = testing::read_text(work() / "predicted.csv");
  expect_contains(table, {"# mode: (b) E* from the measured G'",
                          "the model's systematic error in mode b (tabulated)", "\n0.01,",
                          "\n100,"});
  EXPECT_EQ(softglass::testing::table_header(table),
            "shear_rate [1/s],shear_stress [Pa],N1 [Pa],N2 [Pa],shear_stress_band [Pa],N1_band "
            "[Pa],N2_band [Pa],shear_stress_model_error [Pa],extrapolated [1]");
  const Outcome c = bridge(base + " --plateau-modulus 143 --yield-stress 15");
  ASSERT_EQ(c.code, 0) << c.err;
  expect_contains(c.out, {"# mode: (c) measured yield stress", "rates rescaled by the yield strains"});
  for (const auto& [arguments, words] : std::vector<std::pair<std::string, std::string>>{
           {base + " -o x.csv", "no E*"},
           {base + " --yield-stress 15 -o x.csv", "mode (c) needs"},
           {base + " --modulus 3000 --fit-to missing.csv -o x.csv", "excludes"},
           {"predict " + law + " --phi 0.95 --viscosity 1e-3 --modulus 3e3 --rates 1 -o x.csv",
            "outside the simulated range"},
           {"predict " + law + " --phi 0.85 --viscosity 1e-3 --modulus 3e3 --rates nope -o x.csv",
            "neither a list of numbers nor a file"}}) {
    const Outcome refused = bridge(arguments);
    EXPECT_EQ(refused.code, 2) << arguments;
    expect_contains(refused.err, {words});
    EXPECT_FALSE(fs::exists(work() / "x.csv")) << arguments;
  }
  const Outcome tabulated = bridge("material " + law +
                                   " --phi 0.85 --plateau-modulus 143 --viscosity 0.89e-3 "
                                   "--tabulated -o tabulated.prm");
  ASSERT_EQ(tabulated.code, 0) << tabulated.err;
  expect_contains(testing::read_text(work() / "tabulated.prm"),
                  {"set model        = tabulated", "set source       = (b) E* from the measured G'",
                   "set rates        = ", "set N2 values"});
  const Outcome c_mode = bridge("material " + law +
                                " --phi 0.85 --plateau-modulus 143 --viscosity 0.89e-3 "
                                "--yield-stress 15 --tabulated -o c.prm");
  ASSERT_EQ(c_mode.code, 0) << c_mode.err;
  expect_contains(testing::read_text(work() / "c.prm"),
                  {"set source       = (c) measured yield stress", "set yield stress = 15 "});
  const Outcome not_tabulated = bridge("material " + law +
                                       " --phi 0.85 --plateau-modulus 143 --viscosity 0.89e-3 "
                                       "--yield-stress 15 -o nc.prm");
  EXPECT_EQ(not_tabulated.code, 2);
  expect_contains(not_tabulated.err, {"add --tabulated"});
  EXPECT_FALSE(fs::exists(work() / "nc.prm"));
}

TEST_F(BridgeCli, RescaleWritesPointsAndCurves) {
  testing::write_text(
      work() / "data.csv",
      "# made up: tau_y = 100 Pa, E* = 40 kPa, gamma_y = 0.03\n"
      "Shear rate [1/s],Stress [Pa]\n"
      "0.001,100.6\n0.01,101.9\n0.1,106.0\n1,118.9\n10,159.6\n100,288.4\n1000,695\n");
  const Outcome o = bridge("rescale data.csv --viscosity 1e-3 --yield-strain 0.03");
  ASSERT_EQ(o.code, 0) << o.err;
  expect_contains(o.out, {"curve 'data'", "E* = ", "(fitted)", "written  rescaled.csv"});
  const std::string curves = testing::read_text(work() / "rescaled_curves.csv");
  expect_contains(softglass::testing::table_header(curves), {"tau_y [Pa]"});
  expect_contains(curves, {"\ndata,"});
  const Outcome mixed = bridge("rescale sweep.csv --viscosity 1e-3 --yield-strain 0.03 -o r2.csv");
  EXPECT_EQ(mixed.code, 2) << "a reduced table is not a measured curve";
  const Outcome no_law = bridge("rescale data.csv --viscosity 1e-3 --phi 0.8 -o r3.csv");
  EXPECT_EQ(no_law.code, 2);
  expect_contains(no_law.err, {"--phi", "need --law"});
}

// Bad input to each subcommand: exit code 2, one message naming the problem,
// and no result file (not even a partial or temporary one).
TEST_F(BridgeCli, BadInputIsRefusedWithExitCodeTwoAndNoOutput) {
  const std::string sweep = testing::read_text(work() / "sweep.csv");
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = sweep;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  testing::SyntheticTruth few;
  few.gamma_tilde = {1e-8, 1e-7, 1e-6};
  testing::SyntheticTruth fluid;
  fluid.yield_strain[2] = 1e-6;  // φ = 0.80 without yield stress
  const std::string curve = "Shear rate [1/s],Stress [Pa]\n";
  const struct {
    std::string file, text, arguments;
    std::vector<std::string> message;
  } cases[] = {
      {"ragged.csv",
       edited("\n0.7,1.000000e-09,5,", "\n0.7,1.000000e-09,"),
       "fit ragged.csv",
       {"ragged.csv, line 3", "cells where the header has"}},
      {"nan.csv",
       edited(",5,1.2868314229e-03", ",5,nan"),
       "fit nan.csv",
       {"nan.csv, line 3", "'sigma [E*]'", "not finite"}},
      {"negative.csv",
       edited(",5,1.2868314229e-03", ",5,-1.2868314229e-03"),
       "fit negative.csv",
       {"line 3", "must be > 0"}},
      {"pascals.csv",
       edited("N1 [E*],", "N1 [Pa],"),
       "fit pascals.csv",
       {"'N1 [Pa]'", "expected 'E*'"}},
      {"few.csv",
       testing::table_csv(testing::make_synthetic_sweep(few, 1)),
       "fit few.csv",
       {"phi = 0.7 has 3 shear rate(s)", "at least 4"}},
      {"fluid.csv",
       testing::table_csv(testing::make_synthetic_sweep(fluid, 1)),
       "fit fluid.csv --bootstrap 20",
       {"phi = 0.8, sigma", "no yield plateau"}},
      {"", "", "fit absent.csv", {"'absent.csv' does not exist"}},
      {"structure.csv",
       "phi [1],gamma_tilde [1],f_m [E*R^2],f_m_se [E*R^2]\n0.7,1e-9,0.01,1e-4\n",
       "fit sweep.csv --structure structure.csv",
       {"f_m columns already"}},
      {"c_nan.csv",
       curve + "0.01,10\n0.1,nan\n1,12\n10,15\n",
       "rescale c_nan.csv",
       {"c_nan.csv, line 3", "not finite"}},
      {"c_negative.csv",
       curve + "0.01,10\n0.1,-11\n1,12\n10,15\n",
       "rescale c_negative.csv",
       {"line 3", "must be > 0"}},
      {"c_few.csv",
       curve + "0.01,10\n0.1,11\n1,12\n",
       "rescale c_few.csv",
       {"3 point(s)", "at least 4"}},
      {"c_fluid.csv",
       curve + "0.01,0.1\n0.1,1\n1,10\n10,100\n100,1000\n",
       "rescale c_fluid.csv",
       {"no yield plateau", "--yield-stress"}},
      {"c_mixed.csv",
       "Shear rate [1/s],Stress [E*]\n0.01,10\n0.1,11\n1,12\n10,15\n",
       "rescale c_mixed.csv",
       {"'E*' is not a stress unit"}},
      {"c_ragged.csv",
       curve + "0.01,10\n0.1\n1,12\n10,15\n",
       "rescale c_ragged.csv",
       {"line 3", "1 cells where the header has 2"}},
      {"", "", "rescale absent.csv", {"'absent.csv' does not exist"}},
      {"law.prm",
       "subsection law\n  set colour = red\nend\n",
       "material law.prm --phi 0.8 --modulus 4e4 --viscosity 1e-3 -o material.prm",
       {"colour"}},
  };
  for (const auto& c : cases) {
    if (!c.file.empty()) testing::write_text(work() / c.file, c.text);
    std::string arguments = c.arguments + " --quiet";
    if (c.arguments.starts_with("rescale"))
      arguments = c.arguments + " --viscosity 1e-3 --yield-strain 0.03";
    if (c.arguments.starts_with("material")) arguments = c.arguments;
    const std::vector<std::string> before = files();
    const Outcome o = bridge(arguments);
    EXPECT_EQ(o.code, 2) << arguments << ": " << o.err;
    for (const std::string& part : c.message) expect_contains(o.err, {part});
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one line: " << o.err;
    EXPECT_EQ(files(), before) << arguments << " left files behind";
    if (!c.file.empty()) fs::remove(work() / c.file);
  }
}

// Every subcommand refuses to replace its results without --force (exit code
// 3) and leaves them untouched.
// A full disk (a file-size limit): exit 1 naming the file the user asked for
// and the reason, and none of the four results left, whole or in part.
// An oscillation table in micro's format (docs/oscillation.md): G′ = G0 up to
// γ0 = 0.01 and ∝ 1/γ0 beyond, G″ = 0.2 G0, at two volume fractions.
std::string oscillation_csv() {
  std::ostringstream s;
  s << "# test oscillation table\nphi [1],omega_tilde [1],gamma0 [1],packings [1],storage [E*],"
       "storage_se [E*],loss [E*],loss_se [E*],G0 [E*],G0_se [E*]\n";
  for (const auto& [phi, g0] : {std::pair(0.8, 0.03), std::pair(0.85, 0.05)})
    for (double g : {1e-4, 1e-3, 1e-2, 1e-1, 1.0})
      s << phi << ",2e-7," << g << ",2," << g0 * (g <= 0.01 ? 1.0 : 0.01 / g) << ",1e-6,"
        << 0.2 * g0 << ",1e-6," << g0 << ",1e-4\n";
  return s.str();
}

// fit --oscillation adds the amplitude-sweep law; amplitude-sweep predicts a
// material's sweep from it and compares a measured one point by point.
TEST_F(BridgeCli, AmplitudeSweepFromTheLawAgainstAMeasuredOne) {
  testing::write_text(work() / "osc.csv", oscillation_csv());
  const Outcome fit = bridge(std::string(kFit) + " --oscillation osc.csv -o law.prm");
  ASSERT_EQ(fit.code, 0) << fit.out << fit.err;
  expect_contains(fit.out, {"amplitude sweep at omega~ = 2e-07", "crossover strain"});
  expect_contains(testing::read_text(work() / "law.prm"), {"subsection amplitude sweep"});

  // Measured: 10 % above the prediction for E* = 1000 Pa at phi = 0.8, in %.
  std::ostringstream data;
  data << "Storage modulus [Pa],Loss modulus [Pa],Angular frequency [rad/s],Oscillation strain "
          "[%]\n";
  for (double g : {2e-4, 1e-3, 5e-3, 3e-2, 0.3})
    data << 1.1 * 30.0 * (g <= 0.01 ? 1.0 : 0.01 / g) << "," << 1.1 * 6.0 << ",0.2," << 100 * g
         << "\n";
  testing::write_text(work() / "measured.csv", data.str());
  const Outcome cmp = bridge(
      "amplitude-sweep law.prm --phi 0.8 --modulus 1000 --viscosity 1e-3 --data measured.csv -o "
      "out");
  ASSERT_EQ(cmp.code, 0) << cmp.out << cmp.err;
  expect_contains(cmp.out,
                  {"5 compared", "predicted at 0.2 rad/s", "crossover strain: measured 0.05",
                   "predicted 0.05", "G' median |error| 9.1 %"});
  const std::string table = testing::read_text(work() / "out/comparison.csv");
  expect_contains(softglass::testing::table_header(table),
                  {"gamma0 [1],storage_measured [Pa],storage_predicted [Pa],storage_error [1]"});
  EXPECT_TRUE(fs::exists(work() / "out/amplitude_sweep.csv"));

  // An amplitude sweep added to a law already fitted keeps its flow laws.
  ASSERT_EQ(bridge(std::string(kFit) + " -o plain.prm").code, 0);
  const Outcome added = bridge("fit --law plain.prm --oscillation osc.csv -o added.prm");
  ASSERT_EQ(added.code, 0) << added.err;
  const std::string plain = testing::read_text(work() / "plain.prm"),
                    with_sweep = testing::read_text(work() / "added.prm");
  const auto body = [](const std::string& text) {
    return text.substr(text.find("subsection law"));
  };
  const std::string flow = body(plain).substr(0, body(plain).rfind("end\n"));
  EXPECT_EQ(body(with_sweep).substr(0, flow.size()), flow) << "the flow laws unchanged";
  EXPECT_TRUE(body(with_sweep).substr(flow.size()).starts_with("  subsection amplitude sweep"));
  expect_contains(with_sweep, {"an amplitude sweep added to a law", "subsection amplitude sweep"});
  EXPECT_EQ(bridge("fit --law plain.prm -o x.prm").code, 2) << "--law needs --oscillation";

  // E* from the measured plateau through the amplitude sweep recovers the
  // ratio of the moduli; by default it is the flow-curve route's (static G0).
  const Outcome plateau = bridge(
      "amplitude-sweep law.prm --phi 0.8 --plateau-modulus 33 --plateau-source amplitude-sweep "
      "--viscosity 1e-3 -o plateau");
  ASSERT_EQ(plateau.code, 0) << plateau.err;
  expect_contains(plateau.out, {"E*       1100 Pa", "amplitude sweep at omega~ = 2e-07"});
  const Outcome route =
      bridge("amplitude-sweep law.prm --phi 0.8 --plateau-modulus 33 --viscosity 1e-3 -o static");
  ASSERT_EQ(route.code, 0) << route.err;
  expect_contains(route.out, {"the law's static G0"});

  // Bad input: a law without an amplitude sweep, data without loss modulus.
  const Outcome no_sweep =
      bridge("amplitude-sweep plain.prm --phi 0.8 --modulus 1000 --viscosity 1e-3 -o x");
  EXPECT_EQ(no_sweep.code, 2);
  expect_contains(no_sweep.err, {"no amplitude sweep", "--oscillation"});
  EXPECT_FALSE(fs::exists(work() / "x")) << "a refused command leaves no folder (issue 65)";
  testing::write_text(work() / "bad.csv",
                      "Storage modulus [Pa],Oscillation strain [%]\n1,1\n2,2\n3,3\n4,4\n");
  const Outcome bad = bridge(
      "amplitude-sweep law.prm --phi 0.8 --modulus 1000 --viscosity 1e-3 --data bad.csv -o y");
  EXPECT_EQ(bad.code, 2);
  expect_contains(bad.err, {"loss-modulus"});
  EXPECT_FALSE(fs::exists(work() / "y/amplitude_sweep.csv")) << "nothing written";
}

// Issue 65: the output folder of amplitude-sweep is refused before any work
// when it cannot take the result (it was a raw "filesystem error", exit code
// 1); a plot that cannot be stored is an error naming the file and the
// reason, with nothing left behind, while a missing gnuplot only costs the
// plot.
TEST_F(BridgeCli, AmplitudeSweepRefusesAnUnusableFolderAndAPlotItCannotStore) {
  testing::write_text(work() / "osc.csv", oscillation_csv());
  ASSERT_EQ(bridge(std::string(kFit) + " --oscillation osc.csv -o law.prm").code, 0);
  testing::write_text(work() / "measured.csv",
                      "Storage modulus [Pa],Loss modulus [Pa],Oscillation strain [%]\n"
                      "33,6.6,0.02\n33,6.6,0.1\n30,6.6,1\n10,6.6,10\n");
  const std::string command =
      "amplitude-sweep law.prm --phi 0.8 --modulus 1000 --viscosity 1e-3 --data measured.csv";
  testing::write_text(work() / "afile", "mine");
  const std::vector<std::string> before = files();
  for (const auto& [output, message] :
       {std::pair<std::string, std::string>{"afile",
                                            "output folder 'afile' is a file, not a folder"},
        {"afile/out", "output folder 'afile/out' cannot be created: 'afile' is a file"},
        {"/proc/softglass-out", "output folder '/proc/softglass-out' cannot be created: "}}) {
    const Outcome o = bridge(command + " -o " + output);
    EXPECT_EQ(o.code, 2) << output << ": " << o.err;
    expect_contains(o.err, {message});
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one line: " << o.err;
    EXPECT_EQ(files(), before);
  }
  EXPECT_EQ(testing::read_text(work() / "afile"), "mine");

  if (fs::exists("/usr/bin/gnuplot")) {
    // The tables fit in 4 KiB, the plot does not.
    const Outcome full = softglass::testing::run_tool_on_full_disk(
        SOFTGLASS_BRIDGE_EXECUTABLE, command + " -o out", work(), dir_ / "capture", 4);
    EXPECT_EQ(full.code, 1) << full.out << full.err;
    expect_contains(full.err, {"cannot write 'out/comparison.png': File too large"});
    EXPECT_EQ(files(), before) << "no result, no folder";
  }
  // Without gnuplot on the path: the tables, and a note that there is no plot.
  const Outcome no_plot = softglass::testing::run_tool(
      "/usr/bin/env",
      "PATH=/nonexistent '" + std::string(SOFTGLASS_BRIDGE_EXECUTABLE) + "' " + command + " -o out",
      work(), dir_ / "capture");
  EXPECT_EQ(no_plot.code, 0) << no_plot.err;
  expect_contains(no_plot.out, {"no plot: gnuplot is not installed"});
  EXPECT_EQ(softglass::testing::file_names(work() / "out"),
            (std::vector<std::string>{"amplitude_sweep.csv", "comparison.csv"}));
}

// Issue 65, class A: two fits into one law started together both exited 0,
// the later replacing the earlier's law and tables. The earlier is held
// (SIGSTOP) after claiming its outputs, the later writes its result, and
// the earlier, let go, is refused at its commit (exit code 3) and leaves the
// later's four files as they were.
TEST_F(BridgeCli, OfTwoFitsIntoOneLawTheLaterCommitIsRefused) {
  softglass::testing::BackgroundTool held(
      SOFTGLASS_BRIDGE_EXECUTABLE, "fit sweep.csv --packings runs.csv --bootstrap 2000 --quiet",
      work(), dir_ / "held");
  // The last of its four outputs it claims.
  const fs::path claimed = work() / ("law_constants.csv.tmp" + std::to_string(held.pid()));
  ASSERT_TRUE(softglass::testing::wait_until([&] { return fs::exists(claimed); }, 60));
  held.signal(SIGSTOP);
  ASSERT_FALSE(fs::exists(work() / "law.prm")) << "held too late";
  const Outcome later = bridge(kFit);
  ASSERT_EQ(later.code, 0) << later.err;
  std::vector<std::string> texts;
  for (const char* name : {"law.prm", "law_phi.csv", "law_points.csv", "law_constants.csv"})
    texts.push_back(testing::read_text(work() / name));
  std::vector<std::string> result = files();  // and the held fit's temporaries
  std::erase_if(result,
                [](const std::string& name) { return name.find(".tmp") != std::string::npos; });
  held.signal(SIGCONT);
  const auto ended = held.wait();
  EXPECT_EQ(ended.code, 3) << ended.err;
  expect_contains(ended.err, {"'law.prm' was written by another process while this one ran",
                              "that result is kept"});
  EXPECT_EQ(files(), result) << "no temporary, no file of the refused fit";
  std::size_t k = 0;
  for (const char* name : {"law.prm", "law_phi.csv", "law_points.csv", "law_constants.csv"})
    EXPECT_EQ(testing::read_text(work() / name), texts[k++]) << name;
}

TEST_F(BridgeCli, AFullDiskNamesTheFileAndTheReason) {
  const Outcome o = softglass::testing::run_tool_on_full_disk(SOFTGLASS_BRIDGE_EXECUTABLE, kFit,
                                                              work(), dir_ / "capture", 4);
  EXPECT_EQ(o.code, 1) << o.err;
  expect_contains(o.err, {"cannot write 'law", "File too large"});
  EXPECT_EQ(files(), (std::vector<std::string>{"runs.csv", "sweep.csv"}));
}

TEST_F(BridgeCli, ExistingResultsAreKeptWithoutForce) {
  // τ = 100 (1 + 80 x^½) Pa and N1 = 40 Pa + 20 · 100 x^½ Pa: both panels of Fig. 5.
  testing::write_text(work() / "data.csv",
                      "Shear rate [1/s],Stress [Pa],N1 [Pa]\n0.001,100.6,40.15\n0.01,101.9,40.48\n"
                      "0.1,106.0,41.5\n1,118.9,44.7\n10,159.6,54.9\n100,288.4,87.1\n");
  ASSERT_EQ(bridge(kFit).code, 0);
  const std::string material = "material law.prm --phi 0.8 --modulus 4e4 --viscosity 1e-3 -o m.prm";
  const std::string rescale = "rescale data.csv --viscosity 1e-3 --yield-strain 0.03 -o r.csv";
  ASSERT_EQ(bridge(material).code, 0);
  ASSERT_EQ(bridge(rescale).code, 0);
  for (const std::string& command : {material, rescale}) {
    const std::vector<std::string> before = files();
    const std::string output = command.ends_with("m.prm") ? "m.prm" : "r.csv";
    const std::string text = testing::read_text(work() / output);
    const Outcome o = bridge(command);
    EXPECT_EQ(o.code, 3) << command;
    expect_contains(o.err, {output, "--force"});
    EXPECT_EQ(testing::read_text(work() / output), text);
    EXPECT_EQ(files(), before);
    EXPECT_EQ(bridge(command + " --force").code, 0);
  }
}

// scripts/plot_bridge.py draws its figures from the tables `fit` and `rescale`
// write (skipped where python3 with matplotlib is not installed).
TEST_F(BridgeCli, PlotScriptDrawsTheFiguresFromTheTables) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "/usr/bin/python3 with matplotlib is not installed";
  }
  const std::string script = "/usr/bin/python3 '" SOFTGLASS_SOURCE_DIR "/scripts/plot_bridge.py' ";
  ASSERT_EQ(bridge(kFit).code, 0);
  // τ = 100 (1 + 80 x^½) Pa and N1 = 40 Pa + 20 · 100 x^½ Pa: both panels of Fig. 5.
  testing::write_text(work() / "data.csv",
                      "Shear rate [1/s],Stress [Pa],N1 [Pa]\n0.001,100.6,40.15\n0.01,101.9,40.48\n"
                      "0.1,106.0,41.5\n1,118.9,44.7\n10,159.6,54.9\n100,288.4,87.1\n");
  ASSERT_EQ(bridge("rescale data.csv --viscosity 1e-3 --yield-strain 0.03").code, 0);
  const auto run = [&](const std::string& arguments) {
    return std::system(
        ("cd '" + work().string() + "' && " + script + arguments + " > /dev/null").c_str());
  };
  ASSERT_EQ(run("fit law.prm -o figures"), 0);
  ASSERT_EQ(run("rescale rescaled.csv -o figures"), 0);
  for (const char* name : {"law_flow_curves.png", "law_collapse.png", "law_N1.png", "law_N2.png",
                           "law_force.png", "rescaled_universal.png"}) {
    const std::string png = testing::read_text(work() / "figures" / name);
    EXPECT_TRUE(png.starts_with("\x89PNG")) << name;
  }
  EXPECT_NE(run("fit missing.prm 2> /dev/null"), 0) << "a missing table is an error";
}

// A slip table as `micro slip` writes it, from the reduced law
// V~ gamma~ = 20 sigma~^1.9 at phi = 0.8 (V~ = A sigma~^p / gamma_app).
std::string slip_table() {
  std::string csv =
      "phi,gamma_app,seed,gap,stationary_samples,converged,wall_stress,wall_stress_se,"
      "slip_velocity,slip_velocity_se\n";
  for (const double rate : {1e-6, 1e-5, 1e-4, 1e-3}) {
    const double s = 0.5 * std::sqrt(rate), v = 20.0 * std::pow(s, 1.9) / rate;
    csv += fmt::format("0.8,{},1,1000,250,1,{:.17g},{:.3g},{:.17g},{:.3g}\n", rate, s, 1e-3 * s, v,
                       1e-3 * v);
  }
  return csv;
}

TEST_F(BridgeCli, SlipLawFitsTheTableAndWritesTheMacroFragment) {
  testing::write_text(work() / "slip.csv", slip_table());
  const Outcome reduced = bridge("slip-law slip.csv");
  ASSERT_EQ(reduced.code, 0) << reduced.err;
  expect_contains(reduced.out, {"phi = 0.8: 4 of 4 rows", "A = 20", "p = 1.9", "chi2/dof"});

  const std::string si = "slip-law slip.csv --modulus 4e4 --viscosity 1e-3 --radius 2e-6";
  const Outcome printed = bridge(si);
  ASSERT_EQ(printed.code, 0) << printed.err;
  EXPECT_TRUE(printed.out.starts_with("# softglass bridge slip-law")) << printed.out;
  // beta = A R E*^(1-p)/eta_s
  const double beta = 20.0 * 2e-6 * std::pow(4e4, 1.0 - 1.9) / 1e-3;
  expect_contains(printed.out, {"subsection slip", "set law          = power-law",
                                fmt::format("set coefficient  = {:.6g}", beta),
                                "set exponent     = 1.9", "proportional to R"});

  const Outcome written = bridge(si + " -o slip.prm");
  ASSERT_EQ(written.code, 0) << written.err;
  expect_contains(written.out, {"beta = A R E*^(1-p) / eta_s", "written  slip.prm"});
  expect_contains(testing::read_text(work() / "slip.prm"), {"# command:", "subsection slip"});
  EXPECT_EQ(bridge(si + " -o slip.prm").code, 3);
  EXPECT_EQ(bridge(si + " -o slip.prm --force").code, 0);
}

TEST_F(BridgeCli, SlipLawRefusesBadInputAndWritesNothing) {
  testing::write_text(work() / "slip.csv", slip_table());
  std::string missing = slip_table();
  missing.replace(missing.find("slip_velocity_se"), 16, "other");
  testing::write_text(work() / "missing.csv", missing);
  std::string not_a_number = slip_table();
  not_a_number.replace(not_a_number.find("0.8,1e-06"), 3, "nan");
  testing::write_text(work() / "nan.csv", not_a_number);
  const std::string si = " --modulus 4e4 --viscosity 1e-3 --radius 2e-6 -o out.prm";
  const struct {
    std::string arguments;
    std::vector<std::string> words;
  } cases[] = {
      {"slip-law slip.csv --modulus 4e4 --viscosity 1e-3 --radius 0 -o out.prm", {"--radius"}},
      {"slip-law slip.csv --modulus 4e4 --viscosity 1e-3 --radius -2e-6 -o out.prm", {"--radius"}},
      {"slip-law slip.csv --modulus 4e4 --viscosity 1e-3 -o out.prm", {"--radius"}},
      {"slip-law slip.csv -o out.prm", {"--modulus"}},
      {"slip-law missing.csv" + si, {"missing.csv", "slip_velocity_se", "missing"}},
      {"slip-law nan.csv" + si, {"nan.csv", "line 2", "phi"}},
      {"slip-law slip.csv --max-stress 1e-3" + si, {"phi = 0.8", "1 usable row", "at least 2"}},
      {"slip-law slip.csv --phi 0.9" + si, {"phi = 0.9", "--extrapolate"}},
      {"slip-law absent.csv" + si, {"absent.csv"}},
  };
  for (const auto& c : cases) {
    const Outcome o = bridge(c.arguments);
    EXPECT_EQ(o.code, 2) << c.arguments << "\n" << o.err;
    for (const std::string& w : c.words) expect_contains(o.err, {w});
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_FALSE(fs::exists(work() / "out.prm")) << c.arguments;
  }
}

}  // namespace
}  // namespace softglass::bridge
