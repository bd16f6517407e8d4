// `macro run` from the outside: exit codes and messages for bad input and for
// existing output (common/errors.h), and a complete run of a small scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/h5_file.h"
#include "tests/common/command_line.h"

namespace {

namespace fs = std::filesystem;

class MacroCli : public ::testing::Test {
 protected:
  void SetUp() override {
    write("material.prm",
          "subsection material\n set model = herschel-bulkley\n set yield stress = 10\n"
          " set consistency = 5\n set flow index = 0.5\nend\n");
  }

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }

  // Runs `macro run scene.prm -o out -q <extra>` in the test's folder;
  // returns the exit code and keeps stderr in error_.
  int run(const std::string& scene_text, const std::string& extra = "") {
    write("scene.prm", scene_text);
    const softglass::testing::Outcome o = softglass::testing::run_tool(
        MACRO_EXECUTABLE, "run scene.prm -o out -q " + extra, dir_, dir_ / "capture");
    error_ = o.err;
    return o.code;
  }

  static std::string couette(const std::string& extra) {
    return "set scene = couette\ninclude material.prm\nsubsection couette\n set inner radius = "
           "0.02\n"
           " set outer radius = 0.03\n" +
           extra + "end\nsubsection sweep\n set values = 0.1, 1\nend\n";
  }

  static constexpr const char* kMpirun = "/usr/bin/mpirun";
  static bool mpi_available() {
    // OpenMPI refuses root unless told (CI containers run as root).
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    return fs::exists(kMpirun);
  }
  // `mpirun -n 2 macro run scene.prm -q` with the given options.
  softglass::testing::Outcome run_on_two_ranks(const std::string& options) {
    return softglass::testing::run_tool(
        kMpirun,
        "-n 2 --oversubscribe '" + std::string(MACRO_EXECUTABLE) + "' run scene.prm -q " + options,
        dir_, dir_ / "capture2");
  }
  // The first `columns` values of every row of folder/results.csv.
  std::vector<std::vector<double>> table(const std::string& folder, std::size_t columns = 4) const {
    std::ifstream csv(dir_ / folder / "results.csv");
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(csv, line);) {
      if (line.empty() || line[0] == '#' || line[0] == 'r') continue;  // comments, header
      std::istringstream cells(line);
      std::vector<double>& row = rows.emplace_back();
      for (std::string cell; row.size() < columns && std::getline(cells, cell, ',');)
        row.push_back(std::stod(cell));
    }
    return rows;
  }

  // Unique per process: concurrent suites (another build's ctest) never share it.
  softglass::testing::TemporaryDirectory temporary_;
  const fs::path& dir_ = temporary_.path();
  std::string error_;
};

TEST_F(MacroCli, RunsAndWritesResults) {
  ASSERT_EQ(run(couette("")), 0) << error_;
  std::ifstream csv(dir_ / "out" / "results.csv");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line))
    if (!line.empty() && line[0] != '#') ++rows;
  EXPECT_EQ(rows, 3);  // header + 2 operating points
  EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.txt"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "solution_001.vtu"));
  // results.h5 holds the CSV's table, column by column, with units and the
  // parameter set (the CSV prints 10 significant digits).
  const softglass::H5Group h5 = softglass::H5File::open(dir_ / "out" / "results.h5").root();
  const auto csv_rows = table("out");
  const std::vector<double> omega = h5.read_array("results/rotation_rate").data;
  const std::vector<double> torque = h5.read_array("results/torque").data;
  ASSERT_EQ(torque.size(), csv_rows.size());
  for (std::size_t k = 0; k < torque.size(); ++k) {
    EXPECT_EQ(omega[k], csv_rows[k][0]);
    EXPECT_NEAR(torque[k], csv_rows[k][1], 1e-9 * std::abs(csv_rows[k][1]));
  }
  EXPECT_EQ(h5.dataset_attribute("results/torque", "units"), "N m");
  EXPECT_NE(h5.read_string("parameters").find("set inner radius = 0.02"), std::string::npos);
  EXPECT_EQ(h5.attribute_int("operating_points"), 2);
}

TEST_F(MacroCli, ExistingOutputNeedsForce) {
  ASSERT_EQ(run(couette("")), 0) << error_;
  EXPECT_EQ(run(couette("")), 3);
  EXPECT_EQ(run(couette(""), "--force"), 0) << error_;
}

// Issue 65, class A: two runs into one folder started together both exited 0,
// the later's files replacing the earlier's. The earlier is held (SIGSTOP)
// once it has claimed the folder, the later writes its result, and the
// earlier, let go, is refused at its commit (exit code 3), takes back what it
// had put in place and leaves the later's result whole.
TEST_F(MacroCli, OfTwoRunsIntoOneFolderTheLaterCommitIsRefused) {
  std::string every_point = couette("");
  every_point += "subsection output\n set vtu = all\nend\n";
  write("scene.prm", every_point);
  softglass::testing::BackgroundTool held(MACRO_EXECUTABLE, "run scene.prm -o out -q", dir_,
                                          dir_ / "held");
  const fs::path claimed = dir_ / "out" / ("manifest.txt.tmp" + std::to_string(held.pid()));
  ASSERT_TRUE(softglass::testing::wait_until([&] { return fs::exists(claimed); }, 60));
  held.signal(SIGSTOP);
  ASSERT_FALSE(fs::exists(dir_ / "out" / "manifest.txt")) << "held too late";
  ASSERT_EQ(run(couette("")), 0) << error_;  // one field file, not two
  std::vector<std::string> result = softglass::testing::file_names(dir_ / "out");
  std::erase_if(result,
                [](const std::string& name) { return name.find(".tmp") != std::string::npos; });
  const std::string table = softglass::testing::read_text(dir_ / "out" / "results.csv");
  held.signal(SIGCONT);
  const auto ended = held.wait();
  EXPECT_EQ(ended.code, 3) << ended.err;
  EXPECT_NE(ended.err.find("another process put its result in 'out' while this one ran"),
            std::string::npos)
      << ended.err;
  EXPECT_EQ(softglass::testing::file_names(dir_ / "out"), result)
      << "no temporary, no file of the refused run";
  EXPECT_EQ(softglass::testing::read_text(dir_ / "out" / "results.csv"), table);
}

// Issue 65, class B2: an output folder that is a file or cannot be created
// was "filesystem error: cannot create directories", exit code 1.
TEST_F(MacroCli, AnOutputFolderThatCannotBeMadeIsBadInputNamingIt) {
  write("scene.prm", couette(""));
  write("taken", "a file, not a folder\n");
  for (const auto& [output, message] :
       {std::pair<std::string, std::string>{"taken",
                                            "output folder 'taken' is a file, not a folder"},
        {"taken/out", "output folder 'taken/out' cannot be created: 'taken' is a file"},
        {"/proc/softglass-out", "output folder '/proc/softglass-out' cannot be created: "}}) {
    const auto o = softglass::testing::run_tool(MACRO_EXECUTABLE, "run scene.prm -q -o " + output,
                                                dir_, dir_ / "capture");
    EXPECT_EQ(o.code, 2) << output << ": " << o.err;
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one line: " << o.err;
  }
  EXPECT_EQ(softglass::testing::read_text(dir_ / "taken"), "a file, not a folder\n");
}

TEST_F(MacroCli, UnknownKeyIsNamed) {
  EXPECT_EQ(run(couette(" set inner radios = 0.02\n")), 2);
  EXPECT_NE(error_.find("inner radios"), std::string::npos) << error_;
}

// Text the patterns accept but no double holds (found by SceneFileFuzz): bad
// input naming the entry, not a deal.II exception (exit code 1).
TEST_F(MacroCli, NumbersNoDoubleHoldsAreBadInput) {
  EXPECT_EQ(run(couette(" set length = 1e-320\n")), 2);
  EXPECT_NE(error_.find("length"), std::string::npos) << error_;
  std::string sweep = couette("");
  sweep.replace(sweep.find("0.1, 1"), 6, "0.1, 4.9e-324");
  EXPECT_EQ(run(sweep), 2);
  EXPECT_NE(error_.find("sweep: values"), std::string::npos) << error_;
}

// Messages name the line the user wrote, not the line of the text with its
// includes expanded; a refused run creates no output folder; command-line
// mistakes are reported like every other error.
TEST_F(MacroCli, ErrorsNameTheUsersLineAndLeaveNothingBehind) {
  EXPECT_EQ(run("set scene = couette\ninclude material.prm\nsubsection couette\n"
                " set inner radios = 0.02\nend\n"),
            2);
  EXPECT_NE(error_.find("line 4 of file 'scene.prm'"), std::string::npos) << error_;
  EXPECT_EQ(run(couette(" set length = -1\n")), 2);
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refused run creates nothing";
  EXPECT_EQ(run(couette(""), "--no-such-option"), 2);
  EXPECT_EQ(error_.rfind("macro: error: ", 0), 0u) << error_;
  EXPECT_EQ(std::count(error_.begin(), error_.end(), '\n'), 1) << "one line: " << error_;
}

// Entries of a scene the file does not choose were ignored in silence: a
// channel's pressure gradients ran as the default cone and plate's angular
// velocities. Now refused, naming the entry, the scene in force and the fix.
TEST_F(MacroCli, EntriesOfAnotherSceneAreRefused) {
  EXPECT_EQ(run("include material.prm\nsubsection channel\n set half height = 0.01\nend\n"
                "subsection sweep\n set values = 100, 1000\nend\n"),
            2);
  for (const char* part : {"line 3 of file", "'channel/half height' is set, but the scene is 'cone-plate'",
                           "does not set scene", "set scene = channel"})
    EXPECT_NE(error_.find(part), std::string::npos) << part << " in " << error_;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  EXPECT_EQ(run(couette("") + "subsection duct\n set width = 0.01\nend\n"), 2);
  EXPECT_NE(error_.find("'duct/width' is set, but the scene is 'couette'"), std::string::npos)
      << error_;
}

// Slip walls: the scene's own wall names only (a name of no wall, or of
// another scene's wall, is refused when the file is read), a slip law with
// its coefficients stated and allowed, and not with the augmented Lagrangian.
TEST_F(MacroCli, SlipInputsAreCheckedNamingTheEntry) {
  const std::string law = "subsection slip\n set coefficient = 2e-5\n set exponent = 2\nend\n";
  for (const char* wall : {"rotor", "cone", "bob, plate"}) {
    EXPECT_EQ(run(couette(std::string(" set slip walls = ") + wall + "\n") + law), 2) << wall;
    EXPECT_NE(error_.find("slip walls"), std::string::npos) << error_;
  }
  EXPECT_EQ(run(couette(" set slip walls = bob\n") +
                "subsection slip\n set coefficient = -1e-5\n set exponent = 2\nend\n"),
            2);
  EXPECT_NE(error_.find("slip: 'coefficient' = -1e-05 is not allowed"), std::string::npos)
      << error_;
  EXPECT_EQ(run(couette(" set slip walls = cup\n")), 2);  // the law's coefficients unset
  EXPECT_NE(error_.find("slip: 'coefficient' = 0 is not allowed"), std::string::npos) << error_;
  EXPECT_EQ(run(couette(" set slip walls = cup\n") +
                "subsection slip\n set coefficient = 2e-5\n set exponent = 0\nend\n"),
            2);
  EXPECT_NE(error_.find("slip: 'exponent' = 0 is not allowed"), std::string::npos) << error_;
  EXPECT_EQ(run(couette(" set slip walls = bob\n") + law +
                "subsection solver\n set method = augmented-lagrangian\nend\n"),
            2);
  EXPECT_NE(error_.find("augmented-lagrangian cannot take slip walls"), std::string::npos)
      << error_;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refused run creates nothing";
  EXPECT_EQ(run(couette(" set slip walls = bob, cup\n") + law), 0) << error_;
}

TEST_F(MacroCli, UnitsAfterNumbersAreRejected) {
  EXPECT_EQ(run(couette(" set length = 50 mm\n")), 2);
  EXPECT_NE(error_.find("length"), std::string::npos) << error_;
}

TEST_F(MacroCli, NonPhysicalValuesAreNamed) {
  EXPECT_EQ(run(couette(" set length = -1\n")), 2);
  EXPECT_NE(error_.find("couette: length = -1"), std::string::npos) << error_;
  EXPECT_EQ(run("set scene = couette\ninclude material.prm\nsubsection couette\n set inner radius "
                "= 0.03\n"
                " set outer radius = 0.02\nend\n"),
            2);
  EXPECT_NE(error_.find("outer radius"), std::string::npos) << error_;
}

TEST_F(MacroCli, UnreadableMeshIsNamed) {
  write("broken.msh", "this is not a mesh\n");
  EXPECT_EQ(run("set scene = duct\ninclude material.prm\nsubsection duct\n set section = gmsh\n"
                " set mesh file = broken.msh\nend\n"),
            2);
  EXPECT_NE(error_.find("broken.msh"), std::string::npos) << error_;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "results.csv"));
}

TEST_F(MacroCli, MissingIncludeIsNamed) {
  EXPECT_EQ(run("set scene = couette\ninclude nowhere.prm\n"), 2);
  EXPECT_NE(error_.find("nowhere.prm"), std::string::npos) << error_;
}

// Issue 19, class 3: values that pass their own range but overflow what a
// solve derives from them were computation failures (exit 1, "rate scale =
// inf", a failed factorisation). Now bad input naming the entry, its file and
// line, before anything is written.
TEST_F(MacroCli, AbsurdValuesAreBadInputNamingTheEntry) {
  EXPECT_EQ(run(couette(" set length = 1e300\n")), 2);
  EXPECT_NE(error_.find("couette/length = 1e+300 (line 6 of file 'scene.prm')"), std::string::npos)
      << error_;
  // A finite yield stress whose viscosity scale tau_y/eps is not, from the
  // included material file.
  write("material.prm",
        "subsection material\n set model = herschel-bulkley\n set yield stress = 1e99\n"
        " set consistency = 5\n set flow index = 0.5\nend\n");
  EXPECT_EQ(run(couette("")), 2);
  for (const char* part : {"viscosity scale", "material/yield stress = 1e+99 (line 3 of file",
                           "material.prm"})
    EXPECT_NE(error_.find(part), std::string::npos) << part << " in " << error_;
  SetUp();
  // A Stokes scene whose mesh (40 diameters across) has no representable volume.
  EXPECT_EQ(run("set scene = cylinder\ninclude material.prm\nsubsection cylinder\n"
                " set diameter = 1e98\nend\n"),
            2);
  EXPECT_NE(error_.find("cylinder/diameter = 1e+98 (line 4 of file 'scene.prm')"),
            std::string::npos)
      << error_;
  // A sweep point whose power scale overflows.
  std::string sweep = couette("");
  sweep.replace(sweep.find("0.1, 1"), 6, "0.1, 1e99");
  EXPECT_EQ(run(sweep), 2);
  EXPECT_NE(error_.find("at rotation_rate = 1e+99"), std::string::npos) << error_;
  EXPECT_NE(error_.find("sweep/values = 1e+99 (line 8 of file 'scene.prm')"), std::string::npos)
      << error_;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refused run creates nothing";
}

// Issue 19, class 3, dimensionless: each value representable, but a Bingham
// number or a flow index beyond what the solver was measured to converge on
// (bench/solver_envelope.sh) failed in the solve (exit 1). Now bad input
// naming the entry that made it.
TEST_F(MacroCli, BeyondTheSolversMeasuredEnvelopeIsBadInputNamingTheEntry) {
  // Bi = 10 Pa/(1e-12 Pa s^½ · (0.36 /s)^½) ≈ 1.7e13 at Ω = 0.1 rad/s.
  write("material.prm",
        "subsection material\n set model = herschel-bulkley\n set yield stress = 10\n"
        " set consistency = 1e-12\n set flow index = 0.5\nend\n");
  EXPECT_EQ(run(couette("")), 2);
  for (const char* part : {"Bingham number", "at rotation_rate = 0.1",
                           "material/consistency = 1e-12 (line 4 of file", "up to 1e+10"})
    EXPECT_NE(error_.find(part), std::string::npos) << part << " in " << error_;
  write("material.prm",
        "subsection material\n set model = herschel-bulkley\n set yield stress = 10\n"
        " set consistency = 5\n set flow index = 0.001\nend\n");
  EXPECT_EQ(run(couette("")), 2);
  for (const char* part : {"flow index n = 0.001", "material/flow index = 0.001 (line 5 of file",
                           "from 0.01 to 2"})
    EXPECT_NE(error_.find(part), std::string::npos) << part << " in " << error_;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refused run creates nothing";
}

// A flow the mesh cannot resolve (a yielded layer around a thin bob, thinner
// than the first of four cells across a 15 mm gap) is solved and written with
// its error estimate, and said on stderr even when quiet.
TEST_F(MacroCli, AnUnresolvedFlowIsWrittenWithAWarning) {
  write("material.prm",
        "subsection material\n set model = herschel-bulkley\n set yield stress = 15.36\n"
        " set consistency = 4.72\n set flow index = 0.1\nend\n");
  EXPECT_EQ(run("set scene = couette\ninclude material.prm\nsubsection couette\n"
                " set inner radius = 1e-4\n set outer radius = 0.0152\n set end effects = false\n"
                " set gap cells = 4\nend\nsubsection solver\n set preset = fast\nend\n"
                "subsection sweep\n set values = 1e-3\nend\n"),
            0)
      << error_;
  EXPECT_NE(error_.find("warning: the estimated relative torque error reaches"), std::string::npos)
      << error_;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "results.csv"));
  // The castor-oil cell itself is resolved: no warning.
  EXPECT_EQ(run("set scene = couette\ninclude material.prm\nsubsection couette\n"
                " set inner radius = 0.014\n set outer radius = 0.0152\n set end effects = false\n"
                "end\nsubsection sweep\n set values = 1e-3, 50\nend\n",
                "--force"),
            0)
      << error_;
  EXPECT_EQ(error_.find("warning"), std::string::npos) << error_;
}

// Issue 19, class 5: a forced run into a used folder left the previous run's
// extra field files beside the new ones. Now the folder holds the new run's
// files (and what the user put there), listed in manifest.txt.
TEST_F(MacroCli, ForcedRunLeavesOnlyTheNewRunsFiles) {
  std::string every_point = couette("");
  every_point += "subsection output\n set vtu = all\nend\n";
  every_point.replace(every_point.find("0.1, 1"), 6, "0.1, 0.3, 1");
  ASSERT_EQ(run(every_point), 0) << error_;
  write("out/notes.txt", "the user's own\n");
  ASSERT_EQ(softglass::testing::file_names(dir_ / "out").size(), 8u);
  ASSERT_EQ(run(couette(""), "--force"), 0) << error_;
  EXPECT_EQ(softglass::testing::file_names(dir_ / "out"),
            (std::vector<std::string>{"manifest.txt", "notes.txt", "results.csv", "results.h5",
                                      "solution_001.vtu", "summary.txt"}));
  std::ifstream manifest(dir_ / "out" / "manifest.txt");
  std::vector<std::string> listed;
  for (std::string line; std::getline(manifest, line);)
    if (!line.starts_with('#')) listed.push_back(line);
  EXPECT_EQ(listed, (std::vector<std::string>{"results.csv", "results.h5", "solution_001.vtu",
                                              "summary.txt"}));
  // A forced run refused for bad input leaves that result as it was.
  EXPECT_EQ(run(couette(" set length = -1\n"), "--force"), 2);
  EXPECT_EQ(softglass::testing::file_names(dir_ / "out").size(), 6u);
}

// Issue 19, class 7: a misspelled subsection in an included file is named at
// its own line of its own file (deal.II 9.4 words this error "Line <N> of file
// <F: There is no such subsection...", without the closing '>').
TEST_F(MacroCli, MisspelledSubsectionInAnIncludedFileIsLocated) {
  write("geometry.prm", "# the bob\nsubsection couete\n set inner radius = 0.02\nend\n");
  EXPECT_EQ(run("set scene = couette\ninclude material.prm\ninclude geometry.prm\n"), 2);
  EXPECT_NE(error_.find("line 2 of file"), std::string::npos) << error_;
  EXPECT_NE(error_.find("geometry.prm"), std::string::npos) << error_;
  EXPECT_NE(error_.find("couete"), std::string::npos) << error_;
}

// Issue 19, class 8: a sweep estimated to take long is announced, with the
// number of solves and the estimate, before the first solve.
TEST_F(MacroCli, LongSweepStatesItsPlanFirst) {
  write("scene.prm",
        "set scene = cavity\ninclude material.prm\nsubsection solver\n set preset = accurate\n"
        "end\nsubsection sweep\n set first = 1\n set last = 10\n set points = 3000\nend\n"
        "subsection output\n set vtu = none\nend\n");
  // Stopped after a few seconds: the plan is the first thing it says.
  const softglass::testing::Outcome o = softglass::testing::run_tool(
      "/usr/bin/timeout", "10 '" + std::string(MACRO_EXECUTABLE) + "' run scene.prm -o out -q",
      dir_, dir_ / "capture");
  EXPECT_NE(o.err.find("macro: plan: 3000 operating points"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("preset accurate: about"), std::string::npos) << o.err;
  EXPECT_EQ(run(couette("")), 0);
  EXPECT_EQ(error_.find("plan"), std::string::npos) << "short runs say nothing: " << error_;
}

// `mpirun -n 2 macro run` splits the operating points over the ranks; the
// table must be the serial one. The runs differ only in the warm start of the
// second rank's first point, and Newton stops when its update is below 1e-10
// of max |u| (solver_settings.h): torques agree to 1e-9 relative, and the
// error estimates — differences of nearby solutions, so more sensitive — to
// 1e-6. Skipped without mpirun.
TEST_F(MacroCli, TwoRanksGiveTheSerialTable) {
  if (!mpi_available()) GTEST_SKIP() << "no " << kMpirun;
  std::string scene = couette("");
  scene.replace(scene.find("0.1, 1"), 6, "0.1, 0.3, 1, 3");
  ASSERT_EQ(run(scene), 0) << error_;
  const auto parallel = run_on_two_ranks("-o out2");
  ASSERT_EQ(parallel.code, 0) << parallel.err;
  const auto serial = table("out"), split = table("out2");
  ASSERT_EQ(serial.size(), 4u);
  ASSERT_EQ(split.size(), serial.size());
  for (std::size_t k = 0; k < serial.size(); ++k) {
    EXPECT_EQ(split[k][0], serial[k][0]);
    EXPECT_NEAR(split[k][1], serial[k][1], 1e-9 * serial[k][1]) << k;
    for (int c : {2, 3}) EXPECT_NEAR(split[k][c], serial[k][c], 1e-6 * std::abs(serial[k][c])) << k;
  }
}

// Whatever stops rank 0 from claiming the output folder (here `-o` names a
// file) stops the other ranks too: they waited for it for ever before.
TEST_F(MacroCli, TwoRanksStopTogetherWhenTheFolderCannotBeClaimed) {
  if (!mpi_available()) GTEST_SKIP() << "no " << kMpirun;
  write("scene.prm", couette(""));
  write("taken", "a file, not a folder\n");
  const auto o = softglass::testing::run_tool(
      "/usr/bin/timeout", "300 " + std::string(kMpirun) + " -n 2 --oversubscribe '" +
                              std::string(MACRO_EXECUTABLE) + "' run scene.prm -q -o taken",
      dir_, dir_ / "capture2");
  EXPECT_NE(o.code, 0);
  EXPECT_NE(o.code, 124) << "timed out: a rank waited for rank 0";
  EXPECT_NE(o.err.find("taken"), std::string::npos) << o.err;
}

// Two ranks sharing one point's mesh (the Couette cell with its bottom: a 2D
// meridian section, distributed over both ranks) follow the serial run's path
// — same refinements, same Newton steps, every decision taken on global
// sums — so the mesh is the same and the torque differs by rounding only
// (measured: all 10 printed digits equal; 1e-9 allowed, as above). The VTU
// file of the shared mesh holds every cell once.
TEST_F(MacroCli, TwoRanksSharingOneMeshGiveTheSerialTorque) {
  if (!mpi_available()) GTEST_SKIP() << "no " << kMpirun;
  const std::string scene =
      "set scene = couette\ninclude material.prm\nsubsection couette\n set inner radius = 0.02\n"
      " set outer radius = 0.022\n set length = 0.01\n set end effects = true\n"
      " set bottom gap = 0.002\nend\nsubsection solver\n set preset = fast\nend\n"
      "subsection sweep\n set values = 0.5\nend\nsubsection output\n set vtu = last\nend\n";
  ASSERT_EQ(run(scene), 0) << error_;
  const auto parallel = run_on_two_ranks("-o out2 --ranks-per-point 2");
  ASSERT_EQ(parallel.code, 0) << parallel.err;
  const auto serial = table("out", 100), shared = table("out2", 100);  // every column
  ASSERT_EQ(serial.size(), 1u);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_NEAR(shared[0][1], serial[0][1], 1e-9 * serial[0][1]);
  // cells and dofs: fourth and third from the end (before iterations, wall time).
  const std::size_t cells = serial[0].size() - 4, dofs = cells + 1;
  EXPECT_EQ(shared[0][cells], serial[0][cells]);
  EXPECT_EQ(shared[0][dofs], serial[0][dofs]);
  std::ifstream summary(dir_ / "out2" / "summary.txt");
  const std::string text{std::istreambuf_iterator<char>(summary), {}};
  EXPECT_NE(text.find("2 MPI rank(s), 2 per point's mesh"), std::string::npos) << text;
  // Cells of the shared mesh's VTU: the serial file's count (patches of Q2
  // cells are subdivided alike in both).
  const auto vtu_cells = [&](const std::string& folder) {
    std::ifstream vtu(dir_ / folder / "solution_000.vtu");
    const std::string xml{std::istreambuf_iterator<char>(vtu), {}};
    long total = 0;
    for (std::size_t at = xml.find("NumberOfCells=\""); at != std::string::npos;
         at = xml.find("NumberOfCells=\"", at + 1))
      total += std::stol(xml.substr(at + 15));
    return total;
  };
  EXPECT_GT(vtu_cells("out"), 0);
  EXPECT_EQ(vtu_cells("out2"), vtu_cells("out"));
}

}  // namespace
