// `micro slip` driven as a user would: the tables it writes, the plug's slip
// law against the run's own wall stress, a rerun that keeps finished runs and
// refuses those of another computation, and bad slip files refused before
// any work.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "micro_cli_fixture.h"

namespace softglass::micro {
namespace {

// N = 150 at φ = 0.80 between walls (a gap of 7 R), one short run.
std::string slip_file(const std::string& entries, const std::string& scheme = "euler") {
  std::ostringstream s;
  s << "subsection particles\n  set number = 150\n  set volume fraction = 0.80\nend\n"
    << "subsection integrator\n  set scheme = " << scheme << "\nend\n"
    << "subsection walls\n  set strain = 1\n  set sample interval = 0.05\n"
    << "  set output directory = out\n"
    << entries << "end\n";
  return s.str();
}

// The rows of a CSV table as column name → value.
std::vector<std::map<std::string, double>> read_table(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::istringstream header(line); std::getline(header, cell, ',');) names.push_back(cell);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::map<std::string, double> row;
    std::istringstream values(line);
    for (const std::string& name : names)
      if (std::getline(values, cell, ',')) row[name] = std::stod(cell);
    rows.push_back(row);
  }
  return rows;
}

// Linear interpolation in log–log of the plug law's table at speed u.
double plug_stress(const std::vector<std::map<std::string, double>>& plug, double u) {
  for (std::size_t k = 1; k < plug.size(); ++k) {
    const double u0 = plug[k - 1].at("slip_speed"), u1 = plug[k].at("slip_speed");
    if (u < u0 || u > u1) continue;
    const double t = std::log(u / u0) / std::log(u1 / u0);
    return std::exp((1 - t) * std::log(plug[k - 1].at("wall_stress")) +
                    t * std::log(plug[k].at("wall_stress")));
  }
  return std::nan("");
}

TEST_F(MicroCli, SlipWritesTheTablesAndThePlugLawHoldsBelowYield) {
  parameters("s.prm", slip_file("  set apparent rates = 3e-5\n"));
  const Outcome first = micro("--threads 1 slip s.prm --quiet");
  ASSERT_EQ(first.code, 0) << first.out << first.err;
  const auto runs = read_table(work() / "out/slip.csv");
  ASSERT_EQ(runs.size(), 1u);
  const auto plug = read_table(work() / "out/plug_slip.csv");
  ASSERT_EQ(plug.size(), 89u) << "1e-13 ... 1e-2, eight per decade";
  EXPECT_TRUE(fs::exists(work() / "out/runs/phi0.800_g3.00e-05_s1.h5"));

  // At σ_w ≈ σ_y/3 the slab slides as a plug on its rest contacts: the wall
  // stress the run measured is the plug law's at the run's slip speed
  // U = V_s γ̃, to the interpolation of the table (0.2 %) and the few
  // contacts that change under the load (1 %).
  const auto& run = runs.front();
  EXPECT_LT(run.at("bulk_rate"), 0.01);
  const double speed = run.at("slip_velocity") * run.at("gamma_app");
  EXPECT_NEAR(run.at("wall_stress"), plug_stress(plug, speed), 0.012 * run.at("wall_stress"));
  // Above the films' crossovers the law is σ_w ∝ √U (the EHD film), below
  // them ∝ U (films of rest thickness h0).
  const auto& slow = plug[8], &slower = plug[0], &fast = plug[88], &faster = plug[80];
  EXPECT_NEAR(slow.at("wall_stress") / slower.at("wall_stress"), 10.0, 1e-6);
  EXPECT_NEAR(fast.at("wall_stress") / faster.at("wall_stress"), std::sqrt(10.0), 1e-6);

  // A rerun keeps the finished run; another computation in the folder is refused.
  const Outcome again = micro("--threads 1 slip s.prm");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("done before, kept"), std::string::npos) << again.out;
  parameters("s.prm", slip_file("  set apparent rates = 3e-5\n  set central fraction = 0.4\n"));
  const Outcome changed = micro("--threads 1 slip s.prm --quiet");
  EXPECT_EQ(changed.code, 2) << changed.out;
  EXPECT_NE(changed.err.find("finished result of another computation"), std::string::npos)
      << changed.err;
}

TEST_F(MicroCli, SlipRefusesBadFilesBeforeAnyWork) {
  const auto refused = [&](const std::string& text, const std::string& words) {
    expect_refused("slip", text, words);
  };
  refused("subsection particles\n  set number = 150\nend\n", "sets nothing in subsection 'walls'");
  refused(slip_file("  set apparent rates = 1e-5\n", "implicit"), "does not carry the wall films");
  refused(slip_file("  set apparent rates = -1e-5\n"), "apparent rates");
  refused(slip_file("  set apparent rates = nan\n"), "apparent rates");
  refused(slip_file("  set apparent rates = 1e-3, 1e-5, 1e-3\n"), "'apparent rates' lists 0.001 twice");
  refused(slip_file("  set apparent rates = 1e-5\n  set solvent flow = still\n"), "solvent flow");
  refused(slip_file("  set apparent rates = 1e-5\n  set strain = 0.5\n"), "strain");
  refused(slip_file("  set apparent rates = 1e-5\n  set central fraction = 0\n"), "central fraction");
  // 20 particles leave a gap below two diameters.
  std::string few = slip_file("  set apparent rates = 1e-5\n");
  few.replace(few.find("150"), 3, "20");
  refused(few, "gap");
}

// Issue 65, class B2: an output directory that is a file or cannot be made
// was "filesystem error: cannot create directories", exit code 1, and only
// after the first packing was made. Refused before it now, naming the folder.
TEST_F(MicroCli, SlipRefusesAnOutputFolderItCannotMakeBeforeThePacking) {
  testing::write_text(work() / "taken", "mine");
  for (const auto& [folder, message] :
       {std::pair<std::string, std::string>{"taken",
                                            "output folder 'taken' is a file, not a folder"},
        {"taken/out", "output folder 'taken/out' cannot be created: 'taken' is a file"},
        {"/proc/softglass-out", "output folder '/proc/softglass-out' cannot be created: "}}) {
    std::string text = slip_file("  set apparent rates = 3e-5\n");
    text.replace(text.find("directory = out"), 15, "directory = " + folder);
    const Outcome o = micro("--threads 1 slip " + parameters("s.prm", text));
    EXPECT_EQ(o.code, 2) << folder << ": " << o.err;
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
    EXPECT_EQ(o.out.find("packing seed"), std::string::npos) << "no packing made: " << o.out;
  }
  EXPECT_EQ(files_in_work(), (std::vector<std::string>{"s.prm", "taken"}));
}

TEST_F(MicroCli, SlipTemplateDocumentsTheWallsSubsection) {
  const Outcome tmpl = micro("template --slip");
  ASSERT_EQ(tmpl.code, 0);
  for (const char* entry : {"subsection walls", "set apparent rates", "set solvent flow",
                            "set central fraction", "set profile bins"})
    EXPECT_NE(tmpl.out.find(entry), std::string::npos) << entry;
}

}  // namespace
}  // namespace softglass::micro
