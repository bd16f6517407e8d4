// `micro oscillate` driven as a user would: the tables and run files it
// writes, a rerun that skips finished work and refuses another computation in
// the same folder, and bad oscillation files refused before any work, naming
// the entry, with nothing written.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/h5_file.h"
#include "micro_cli_fixture.h"
#include "tests/common/text_checks.h"

namespace softglass::micro {
namespace {

// N = 200 at φ = 0.80 (skin 0.3 for the neighbour grid), an amplitude sweep
// at one frequency whose peak rates run the implicit scheme.
std::string oscillation_file(const std::string& entries, const std::string& frequencies = "1e-6") {
  std::ostringstream s;
  s << "subsection particles\n  set number = 200\n  set volume fraction = 0.80\nend\n"
    << "subsection neighbours\n  set skin = 0.3\nend\n"
    << "subsection oscillation\n  set frequencies = " << frequencies
    << "\n  set samples per cycle = 16\n"
    << "  set output directory = out\n"
    << entries << "end\n";
  return s.str();
}

std::string data_lines(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line, data;
  while (std::getline(in, line))
    if (!line.starts_with("#")) data += line + '\n';
  return data;
}

TEST_F(MicroCli, OscillateWritesTheTablesAndRunFilesAndSkipsFinishedWork) {
  parameters("o.prm", oscillation_file("  set amplitudes = 1e-3, 0.05\n"));
  const Outcome first = micro("--threads 1 oscillate o.prm --quiet");
  ASSERT_EQ(first.code, 0) << first.out << first.err;
  const std::string table = data_lines(work() / "out/oscillation.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3) << "a header and a row per amplitude";
  const std::string header = softglass::testing::table_header(softglass::testing::read_text(work() / "out/oscillation.csv"));
  for (const char* column :
       {"phi [1]", "omega_tilde [1]", "gamma0 [1]", "storage [E*]", "storage_se [E*]",
        "loss [E*]", "loss_film [E*]", "intensity_3 [1]", "e3 [E*]", "v1 [eta_s]", "N1 [E*]",
        "G0 [E*]", "G0_xy [E*]", "periodic_cycles [1]", "converged [1]"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  EXPECT_TRUE(fs::exists(work() / "out/oscillation_packings.csv"));
  EXPECT_TRUE(fs::exists(work() / "out/oscillation.h5"));

  // The run file holds the periodic summary and a closed Lissajous loop.
  const fs::path run = work() / "out/runs/phi0.8000_w1.000e-06_g1.000e-03_seed1.h5";
  ASSERT_TRUE(fs::exists(run));
  const H5File file = H5File::open(run);
  const H5Group g = file.root().group("oscillation");
  EXPECT_EQ(g.read_scalar("amplitude"), 1e-3);
  EXPECT_NEAR(g.read_scalar("peak_gamma_tilde"), 1e-9, 1e-24);
  const std::vector<double> strain = g.group("lissajous").read_array("strain").data;
  ASSERT_EQ(strain.size(), 17u);
  EXPECT_NEAR(strain.front(), strain.back(), 1e-12) << "the loop closes";
  EXPECT_GT(g.group("summary").group("storage").attribute_double("mean"), 0.0);

  const Outcome again = micro("--threads 1 oscillate o.prm --quiet");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("2 cases (2 done)"), std::string::npos) << again.out;
  EXPECT_EQ(again.out.find("run      phi"), std::string::npos) << "nothing is run again";
  EXPECT_EQ(data_lines(work() / "out/oscillation.csv"), table);

  // Another computation in the same folder is refused, naming what changed.
  parameters("o.prm", oscillation_file("  set amplitudes = 1e-3, 0.05\n  set max cycles = 12\n"));
  const Outcome changed = micro("--threads 1 oscillate o.prm --quiet");
  EXPECT_EQ(changed.code, 2) << changed.out;
  EXPECT_NE(changed.err.find("finished result of another computation"), std::string::npos)
      << changed.err;
}

TEST_F(MicroCli, OscillateRefusesBadFilesBeforeAnyWork) {
  const auto refused = [&](const std::string& text, const std::string& words) {
    expect_refused("oscillate", text, words);
  };
  refused("subsection particles\n  set number = 200\nend\n", "sets nothing in subsection 'oscillation'");
  refused(oscillation_file("  set amplitudes = 0.01\n  set samples per cycle = 30\n"),
          "samples per cycle");
  refused(oscillation_file("  set amplitudes = -0.01\n"), "amplitudes");
  refused(oscillation_file("  set amplitudes = 1e-6\n", "1e-10"), "peak shear rate");
  refused(oscillation_file("  set amplitudes = 0.01, 0.01\n"), "lists 0.01 twice");
  refused(oscillation_file("  set amplitudes = nan\n"), "amplitudes");
  refused(oscillation_file("  set amplitudes = 0.01\n  set min cycles = 3\n"), "min cycles");
}

TEST_F(MicroCli, OscillateListsItsCasesAndTemplateDocumentsTheSubsection) {
  parameters("o.prm", oscillation_file("  set amplitudes = 1e-3, 1e-2, 0.1\n  set packings = 2\n"));
  const Outcome list = micro("oscillate o.prm --list");
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("1 volume fractions x 1 frequencies x 3 amplitudes x 2 packings = 6 "
                          "cases"),
            std::string::npos)
      << list.out;
  EXPECT_FALSE(fs::exists(work() / "out")) << "--list runs nothing";
  const Outcome tmpl = micro("template --oscillation");
  ASSERT_EQ(tmpl.code, 0);
  for (const char* entry : {"set amplitudes", "set frequencies", "set samples per cycle",
                            "set min periodic cycles", "set target relative error"})
    EXPECT_NE(tmpl.out.find(entry), std::string::npos) << entry;
}

}  // namespace
}  // namespace softglass::micro
