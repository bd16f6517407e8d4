// `micro sweep` driven as a user would: the tables it writes, a rerun that
// skips finished work, the lock that refuses a second sweep on one folder,
// batch-array mode, bad sweep files, and the promise that nothing is lost — a
// sweep killed with SIGKILL in the middle of a case and run again ends with
// exactly the table of an uninterrupted one.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <thread>
#include <tuple>

#include "common/h5_file.h"
#include "micro/io/checkpoint_file.h"
#include "micro/sweep/directory_lock.h"
#include "micro_cli_fixture.h"
#include "tests/common/text_checks.h"

namespace softglass::micro {
namespace {

// N = 200 needs a skin below ~0.6 for the neighbour grid; short runs. No
// quasi-static case unless `sweep_entries` asks for it (an entry is set once
// per file).
std::string sweep_file(const std::string& directory, const std::string& sweep_entries,
                       double max_strain, std::size_t particles = 200) {
  std::ostringstream s;
  s << "subsection sweep\n  set preset = custom\n  set particles = " << particles
    << "\n  set output directory = " << directory << "\n"
    << (sweep_entries.find("set quasi-static =") == std::string::npos
            ? "  set quasi-static = false\n"
            : "")
    << sweep_entries << "end\n"
    << "subsection neighbours\n  set skin = 0.3\nend\n"
    << "subsection shear\n  set min strain = " << max_strain
    << "\n  set max strain = " << max_strain
    << "\n  set min stationary strain = 0.5\n  set snapshot interval = 0\nend\n";
  return s.str();
}

// The data lines of a CSV file (provenance comments dropped).
std::string table_data(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line, data;
  while (std::getline(in, line))
    if (!line.starts_with("#")) data += line + '\n';
  return data;
}

std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Starts `micro <arguments>` in `work` in the background and kills it with
// SIGKILL as soon as `checkpoint` exists, before `result` does.
void kill_after_checkpoint(const fs::path& work, const std::string& arguments,
                           const fs::path& checkpoint, const fs::path& result) {
  const fs::path pid_file = work / "pid";
  const std::string start = "cd '" + work.string() + "' && ('" SOFTGLASS_MICRO_EXECUTABLE "' " +
                            arguments + " > killed.log 2>&1 & echo $! > '" + pid_file.string() +
                            "')";
  ASSERT_EQ(std::system(start.c_str()), 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(checkpoint) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(checkpoint)) << "no checkpoint within 2 minutes";
  const pid_t pid = std::stoi(testing::read_text(pid_file));
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  // Gone (or a zombie nobody reaps yet: it runs no more either way).
  for (int k = 0; k < 100 && ::kill(pid, 0) == 0; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_FALSE(fs::exists(result)) << "killed too late: the case had finished";
}

TEST_F(MicroCli, SweepWritesTheFlowCurveTablesAndSkipsFinishedWorkOnARerun) {
  const std::string entries =
      "  set volume fractions = 0.70, 0.80\n  set gamma dot tildes = 1e-4, 3e-5\n"
      "  set packings = 1\n";
  parameters("s.prm", sweep_file("out", entries, 1.0));
  const Outcome first = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(first.code, 0) << first.out << first.err;
  const std::string table = table_data(work() / "out/flow_curve.csv");
  EXPECT_EQ(count_lines(table), 1 + 4u) << "a header and one row per (phi, gamma~)";
  const std::string header = softglass::testing::table_header(softglass::testing::read_text(work() / "out/flow_curve.csv"));
  for (const char* column : {"phi [1]", "gamma_tilde [1]", "packings [1]", "sigma [E*]",
                             "sigma_se [E*]", "N1_viscous [E*]", "N2_elastic_se [E*]",
                             "pressure [E*]", "Z [1]", "G0 [E*]", "G0_se [E*]", "converged [1]"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  EXPECT_EQ(count_lines(table_data(work() / "out/flow_curve_packings.csv")), 1 + 4u);
  EXPECT_TRUE(fs::exists(work() / "out/flow_curve.h5"));
  EXPECT_EQ(
      std::distance(fs::directory_iterator(work() / "out/packings"), fs::directory_iterator()), 2)
      << "one packing per (phi, seed), shared by both rates";

  const Outcome again = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("4 cases (4 done)"), std::string::npos) << again.out;
  EXPECT_EQ(again.out.find("run      phi"), std::string::npos) << "nothing is run again";
  EXPECT_EQ(table_data(work() / "out/flow_curve.csv"), table);

  // The folder's finished work is reused only for the same computation: a
  // changed contact law, N or run length is refused naming the entry, and the
  // table is left as it was (it used to be rewritten from the old runs under
  // a header naming the new parameters; issue 19, class 1).
  std::string longer = sweep_file("out", entries, 1.0);
  longer.replace(longer.find("set max strain = 1\n"), 19, "set max strain = 1.5\n");
  const std::map<std::string, std::string> changes = {
      {"contact law/law = piecewise",
       sweep_file("out", entries, 1.0) + "subsection contact law\n  set law = hertz\nend\n"},
      {"shear/max strain = 1", longer}};
  for (const auto& [was, text] : changes) {
    parameters("s.prm", text);
    const Outcome changed = micro("--threads 1 sweep s.prm --quiet");
    EXPECT_EQ(changed.code, 2) << changed.err;
    EXPECT_NE(changed.err.find("a finished result of another computation"), std::string::npos)
        << changed.err;
    EXPECT_NE(changed.err.find(was), std::string::npos) << was << " in " << changed.err;
    EXPECT_EQ(table_data(work() / "out/flow_curve.csv"), table);
  }
}

// The columns of a CSV table's data rows, by name (units dropped).
std::vector<std::map<std::string, double>> table_rows(const fs::path& csv) {
  std::istringstream in(table_data(csv));
  std::string line;
  std::vector<std::string> names;
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::vector<std::string> row;
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(cell);
    if (names.empty()) {
      for (const std::string& cell : row) names.push_back(cell.substr(0, cell.find(" [")));
      continue;
    }
    rows.emplace_back();
    for (std::size_t c = 0; c < row.size(); ++c) rows.back()[names.at(c)] = std::stod(row[c]);
  }
  return rows;
}

// The quasi-static case: listed, run alone as a batch-array task, skipped when
// done and redone when not, and the γ̃ = 0 row of the table — σ_y, below the
// stress of every rate, with σ^v = 0.
TEST_F(MicroCli, SweepQuasiStaticCaseIsTheLowEndOfTheFlowCurve) {
  const std::string entries =
      "  set volume fractions = 0.8\n  set gamma dot tildes = 1e-4\n  set packings = 1\n"
      "  set quasi-static = true\n  set quasi-static strain step = 1e-3\n";
  parameters("s.prm", sweep_file("out", entries, 1.0, 128));
  const Outcome list = micro("sweep s.prm --list");
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("1 rates (+ quasi-static) x 1 packings = 2 cases"), std::string::npos)
      << list.out;
  EXPECT_NE(list.out.find("case    0  phi 0.8000  gamma~ 0 (AQS)"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("out/runs/phi0.8000_aqs_seed1.h5"), std::string::npos) << list.out;

  const Outcome alone = micro("--threads 1 sweep s.prm --case 0 --quiet");
  ASSERT_EQ(alone.code, 0) << alone.err;
  const fs::path record = work() / "out/runs/phi0.8000_aqs_seed1.h5";
  {
    const H5File file = H5File::open(record);
    const H5Group shear = file.root().group("shear");
    EXPECT_EQ(shear.attribute_string("protocol"), "aqs");
    EXPECT_EQ(shear.attribute_double("strain_step"), 1e-3);
    EXPECT_EQ(shear.read_scalar("gamma_tilde"), 0.0);
    EXPECT_EQ(shear.group("counters").attribute_int("steps"), 1000);
    EXPECT_GT(shear.group("counters").attribute_int("stress_drops"), 0);
    EXPECT_EQ(shear.group("counters").attribute_int("unconverged_steps"), 0);
    EXPECT_NE(file.root().read_string("parameters").find("quasi-static (AQS) case"),
              std::string::npos);
  }

  const Outcome sweep = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  EXPECT_NE(sweep.out.find("2 cases (1 done)"), std::string::npos) << sweep.out;
  EXPECT_EQ(sweep.out.find("gamma~ 0 (AQS)"), std::string::npos) << "the finished case is skipped";
  const auto rows = table_rows(work() / "out/flow_curve.csv");
  ASSERT_EQ(rows.size(), 2u);
  const auto& aqs = rows[0];
  const auto& rate = rows[1];
  EXPECT_EQ(aqs.at("gamma_tilde"), 0.0);
  EXPECT_EQ(rate.at("gamma_tilde"), 1e-4);
  EXPECT_GT(aqs.at("sigma"), 0.0);
  EXPECT_GT(aqs.at("sigma_se"), 0.0);
  EXPECT_LT(aqs.at("sigma"), rate.at("sigma")) << "sigma_y <= sigma(gamma~)";
  EXPECT_EQ(aqs.at("sigma_viscous"), 0.0);
  EXPECT_EQ(aqs.at("sigma_viscous_se"), 0.0);
  EXPECT_EQ(aqs.at("sigma_film"), 0.0);
  EXPECT_EQ(aqs.at("sigma"), aqs.at("sigma_elastic"));
  EXPECT_EQ(aqs.at("G0"), rate.at("G0")) << "one packing";
  EXPECT_EQ(table_rows(work() / "out/flow_curve_packings.csv").at(0).at("gamma_tilde"), 0.0);

  // A case without its result (killed, say) is run again, to the same numbers.
  const std::string table = table_data(work() / "out/flow_curve.csv");
  fs::remove(record);
  const Outcome again = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("run      phi 0.8000 gamma~ 0 (AQS)"), std::string::npos) << again.out;
  EXPECT_EQ(table_data(work() / "out/flow_curve.csv"), table);
}

// A finished quasi-static run made at a finer setting than the sweep file now
// asks for — a tighter force tolerance, a smaller strain step — resolves the
// request and is kept; one made at a coarser setting is refused, naming the
// heading line that differs. `entry` is the sweep entry, the other setting
// stays at the file's: strain step 1e-3, force tolerance 1e-6.
class SweepKeptRun : public MicroCli {
 protected:
  void expect_finer_quasi_static_run_kept(const std::string& entry, const std::string& made,
                                          const std::string& coarser, const std::string& finer,
                                          const std::string& heading) const;
};

void SweepKeptRun::expect_finer_quasi_static_run_kept(const std::string& entry,
                                                      const std::string& made,
                                                      const std::string& coarser,
                                                      const std::string& finer,
                                                      const std::string& heading) const {
  const auto file_at = [&](const std::string& value) {
    std::string entries =
        "  set volume fractions = 0.8\n  set gamma dot tildes = 1e-4\n"
        "  set packings = 1\n  set quasi-static = true\n";
    for (const auto& [name, fixed] :
         {std::pair<std::string, std::string>{"strain step", "1e-3"}, {"force tolerance", "1e-6"}})
      entries += "  set quasi-static " + name + " = " + (name == entry ? value : fixed) + "\n";
    return sweep_file("out", entries, 0.5, 128);
  };
  parameters("made.prm", file_at(made));
  const Outcome first = micro("--threads 1 sweep made.prm --case 0 --quiet");
  ASSERT_EQ(first.code, 0) << first.err;
  const fs::path record = work() / "out/runs/phi0.8000_aqs_seed1.h5";
  const auto written = fs::last_write_time(record);

  parameters("coarser.prm", file_at(coarser));
  const Outcome again = micro("--threads 1 sweep coarser.prm --case 0 --quiet");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(fs::last_write_time(record), written) << "the finer run is not recomputed";

  parameters("finer.prm", file_at(finer));
  const Outcome refused = micro("--threads 1 sweep finer.prm --case 0 --quiet");
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find(heading + " " + made), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find(heading + " " + finer), std::string::npos) << refused.err;
  EXPECT_EQ(fs::last_write_time(record), written);
}

TEST_F(SweepKeptRun, QuasiStaticRunMadeAtATighterForceTolerance) {
  expect_finer_quasi_static_run_kept("force tolerance", "1e-09", "1e-06", "1e-10",
                                     "minimiser force tolerance");
}

TEST_F(SweepKeptRun, QuasiStaticRunMadeAtASmallerStrainStep) {
  expect_finer_quasi_static_run_kept("strain step", "0.0005", "0.001", "0.00025", "strain step");
}

// A quasi-static case killed after a checkpoint goes on only with the strain
// step and force tolerance it was made with: its record names one of each for
// the whole run. Asked for another (a sweep file, or a default, that changed),
// the rerun is refused, naming the checkpoint and both values, and leaves it
// in place; so is one written before checkpoints kept their parameters, by
// its strain step.
TEST_F(MicroCli, SweepResumesAQuasiStaticCheckpointOnlyAtItsOwnSettings) {
  const auto file_at = [&](const std::string& step, const std::string& tolerance) {
    return sweep_file("out",
                      "  set volume fractions = 0.8\n  set gamma dot tildes = 1e-4\n"
                      "  set packings = 1\n  set quasi-static = true\n"
                      "  set checkpoint steps = 100\n  set quasi-static strain step = " +
                          step + "\n  set quasi-static force tolerance = " + tolerance + "\n",
                      4.0, 128);
  };
  parameters("made.prm", file_at("5e-4", "1e-6"));
  parameters("other_step.prm", file_at("1e-3", "1e-6"));
  parameters("other_tolerance.prm", file_at("5e-4", "1e-8"));
  const fs::path checkpoint = work() / "out/runs/phi0.8000_aqs_seed1.checkpoint.h5";
  kill_after_checkpoint(work(), "--threads 1 sweep made.prm --case 0 --quiet", checkpoint,
                        work() / "out/runs/phi0.8000_aqs_seed1.h5");
  if (HasFatalFailure()) return;

  for (const auto& [file, made, asked] :
       {std::tuple{"other_step.prm", "strain step 0.0005,", "strain step 0.001,"},
        std::tuple{"other_tolerance.prm", "force tolerance 1e-06;", "force tolerance 1e-08;"}}) {
    const Outcome refused = micro(std::string("--threads 1 sweep ") + file + " --case 0 --quiet");
    EXPECT_EQ(refused.code, 2) << file;
    EXPECT_NE(refused.err.find("is the checkpoint of another computation"), std::string::npos)
        << refused.err;
    for (const std::string& named :
         {checkpoint.filename().string(), std::string(made), std::string(asked)})
      EXPECT_NE(refused.err.find(named), std::string::npos) << named << " in " << refused.err;
    EXPECT_TRUE(fs::exists(checkpoint)) << "the checkpoint is kept";
  }

  // A checkpoint from before checkpoints kept their parameters (the same one,
  // rewritten without them): its step is read from its strain over its steps.
  write_checkpoint(checkpoint, read_quasi_static_checkpoint(checkpoint));
  const Outcome older = micro("--threads 1 sweep other_step.prm --case 0 --quiet");
  EXPECT_EQ(older.code, 2);
  EXPECT_NE(older.err.find("was made at quasi-static strain step 0.0005, the run asks for 0.001"),
            std::string::npos)
      << older.err;
  EXPECT_NE(older.err.find(checkpoint.filename().string()), std::string::npos) << older.err;
  EXPECT_TRUE(fs::exists(checkpoint)) << "the checkpoint is kept";

  const Outcome resumed = micro("--threads 1 sweep made.prm --case 0 --quiet");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resumed from its checkpoint"), std::string::npos) << resumed.out;
}

// A preset fixes each run's length whatever the file's subsection shear says:
// `paper` shears 5 strain and averages at least the last 3 (the paper's
// protocol), and the case's record keeps the entries it ran with.
TEST_F(MicroCli, SweepPresetSetsTheLengthOfEveryRun) {
  parameters("s.prm",
             "subsection sweep\n  set preset = paper\n  set particles = 128\n"
             "  set volume fractions = 0.8\n  set gamma dot tildes = 1e-4\n  set packings = 1\n"
             "  set quasi-static = false\n  set output directory = out\nend\n"
             "subsection neighbours\n  set skin = 0.3\nend\n"
             "subsection shear\n  set min strain = 1\n  set max strain = 1\n"
             "  set min stationary strain = 0.5\n  set snapshot interval = 0\nend\n");
  const Outcome o = micro("--threads 1 sweep s.prm --case 0 --quiet");
  ASSERT_EQ(o.code, 0) << o.err;
  const H5File file = H5File::open(work() / "out/runs/phi0.8000_gt1.000e-04_seed1.h5");
  const std::string text = file.root().read_string("parameters");
  for (const char* entry : {"set min strain            = 5", "set max strain            = 5",
                            "set min stationary strain = 3"})
    EXPECT_NE(text.find(entry), std::string::npos) << entry << " in\n" << text;
  const auto strain = file.root().group("shear").group("timeseries").read_array("strain").data;
  ASSERT_FALSE(strain.empty());
  EXPECT_NEAR(strain.back(), 5.0, 0.011) << "sampled every 0.01 up to the preset's 5 strain";
}

TEST_F(MicroCli, SweepRefusesAFolderAnotherSweepHolds) {
  parameters("s.prm", sweep_file("out",
                                 "  set volume fractions = 0.7\n  set gamma dot tildes = 1e-4\n"
                                 "  set packings = 1\n",
                                 1.0));
  const DirectoryLock held(work() / "out");
  const Outcome o = micro("sweep s.prm --quiet");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("another sweep is running"), std::string::npos) << o.err;
}

TEST_F(MicroCli, SweepRefusesBadSweepFiles) {
  parameters("twice.prm", sweep_file("out",
                                     "  set volume fractions = 0.7, 0.70\n  set gamma dot tildes = "
                                     "1e-4\n  set packings = 1\n",
                                     1.0));
  Outcome o = micro("sweep twice.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("'volume fractions' lists 0.7 twice"), std::string::npos) << o.err;

  parameters("bare.prm", sweep_file("out", "", 1.0));
  o = micro("sweep bare.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("preset 'custom' needs"), std::string::npos) << o.err;

  parameters("range.prm", sweep_file("out", "  set volume fractions = 0.5\n", 1.0));
  o = micro("sweep range.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("volume fractions"), std::string::npos) << o.err;

  const std::string one_point =
      "  set volume fractions = 0.7\n  set gamma dot tildes = 1e-4\n  set packings = 1\n";
  parameters("step.prm",
             sweep_file("out", one_point + "  set quasi-static strain step = 0\n", 1.0));
  o = micro("sweep step.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("'quasi-static strain step' = 0; allowed: (0, 0.01]"), std::string::npos)
      << o.err;
  parameters(
      "coarse.prm",
      sweep_file("out",
                 one_point + "  set quasi-static = true\n  set quasi-static strain step = 0.02\n",
                 1.0));
  o = micro("sweep coarse.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("quasi-static strain step"), std::string::npos) << o.err;
  parameters(
      "sparse.prm",
      sweep_file("out",
                 one_point + "  set quasi-static = true\n  set quasi-static strain step = 0.005\n",
                 1.0) +
          "subsection shear\n  set sample interval = 0.002\nend\n");
  o = micro("sweep sparse.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(
      o.err.find("'quasi-static strain step' = 0.005 exceeds shear/'sample interval' = 0.002"),
      std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(work() / "out" / "flow_curve.csv"));
}

// Mistakes that used to cost hours or fail late: a run file given to `micro
// sweep` (it started the default preset), N = 1 (refused once per packing
// after the sweep began), a value wrong only in combination with a sweep's
// volume fraction. Each is one exit-2 message before anything is written.
TEST_F(MicroCli, SweepRefusesMistakesBeforeAnyWork) {
  parameters("run.prm", "subsection particles\n  set number = 200\nend\n");
  Outcome o = micro("sweep run.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("sets nothing in subsection 'sweep': it is not a sweep file"),
            std::string::npos)
      << o.err;

  const std::string one_point =
      "  set volume fractions = 0.7\n  set gamma dot tildes = 1e-4\n  set packings = 1\n";
  parameters("one.prm", sweep_file("out", one_point, 1.0, 1));
  o = micro("sweep one.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("particles = 1; allowed: 0 (the preset's N) or 2"), std::string::npos)
      << o.err;

  parameters("combined.prm",
             sweep_file("out",
                        "  set volume fractions = 0.66, 0.8\n  set gamma dot tildes = 1e-4\n"
                        "  set packings = 1\n",
                        1.0) +
                 "subsection packing\n  set initial volume fraction = 0.7\nend\n");
  o = micro("sweep combined.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("phi = 0.66, packing seed 1: initial volume fraction = 0.7 exceeds"),
            std::string::npos)
      << o.err;
  EXPECT_EQ(o.out.find("packing "), std::string::npos) << "no packing was made:\n" << o.out;
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(MicroCli, SweepRunsOneCaseOfABatchArray) {
  parameters("s.prm",
             sweep_file("out",
                        "  set volume fractions = 0.7\n  set gamma dot tildes = 1e-4, 3e-5\n"
                        "  set packings = 1\n",
                        1.0));
  const Outcome list = micro("sweep s.prm --list");
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("case    1"), std::string::npos) << list.out;
  const Outcome one = micro("--threads 1 sweep s.prm --case 1 --quiet");
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(work() / "out/runs"), fs::directory_iterator()),
            1);
  EXPECT_EQ(micro("sweep s.prm --case 2").code, 2) << "there are cases 0 and 1 only";
  const Outcome gather = micro("sweep s.prm --gather");
  EXPECT_EQ(gather.code, 1) << "one run is missing: the table holds the other, and says so";
  EXPECT_NE(gather.err.find("1 of 2 runs are missing"), std::string::npos) << gather.err;
  EXPECT_EQ(count_lines(table_data(work() / "out/flow_curve.csv")), 1 + 1u);

  // The rest of the sweep: its first line scales the cost model by this
  // machine's pace, the finished case's recorded time over its modelled one.
  const Outcome costs = micro("sweep s.prm --list");
  std::smatch modelled;
  ASSERT_TRUE(std::regex_search(
      costs.out, modelled,
      std::regex(R"(cost +(\S+) core hours for all cases, (\S+) for those pending)")))
      << costs.out;
  const double finished_hours = std::stod(modelled[1]) - std::stod(modelled[2]);
  const fs::path finished_run = fs::directory_iterator(work() / "out/runs")->path();
  const double recorded = H5File::open(finished_run).root().group("timings").read_scalar("total");
  const Outcome rest = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(rest.code, 0) << rest.err;
  std::smatch pace;
  ASSERT_TRUE(std::regex_search(rest.out, pace,
                                std::regex(R"(the 1 finished case took x(\S+) the model's time)")))
      << rest.out;
  // Printed to 3 and 4 significant digits.
  EXPECT_NEAR(std::stod(pace[1]) / (recorded / (finished_hours * 3600.0)), 1.0, 0.01);
}

// The tasks of a batch array whose cases share a packing make it at once when
// it is missing. Now that a commit never replaces another process's file
// (issue 65), the later task uses the packing the earlier wrote instead of
// failing: one task is held (SIGSTOP) once it has claimed the packing, the
// other makes it and runs its case, and the held one, let go, runs its own.
TEST_F(MicroCli, BatchTasksSharingAPackingBothRunTheirCases) {
  parameters("s.prm",
             sweep_file("out",
                        "  set volume fractions = 0.7\n  set gamma dot tildes = 1e-4, 3e-5\n"
                        "  set packings = 1\n",
                        1.0));
  softglass::testing::BackgroundTool held(SOFTGLASS_MICRO_EXECUTABLE,
                                          "--threads 1 sweep s.prm --case 0 --quiet", work(),
                                          dir_ / "held");
  const fs::path claimed =
      work() / ("out/packings/phi0.7000_seed1.h5.tmp" + std::to_string(held.pid()));
  ASSERT_TRUE(softglass::testing::wait_until([&] { return fs::exists(claimed); }, 60));
  held.signal(SIGSTOP);
  const Outcome other = micro("--threads 1 sweep s.prm --case 1 --quiet");
  ASSERT_EQ(other.code, 0) << other.err;
  const std::string packing = testing::read_text(work() / "out/packings/phi0.7000_seed1.h5");
  held.signal(SIGCONT);
  const auto ended = held.wait();
  EXPECT_EQ(ended.code, 0) << ended.err;
  EXPECT_NE(ended.out.find("written meanwhile by another task, used"), std::string::npos)
      << ended.out;
  EXPECT_EQ(testing::read_text(work() / "out/packings/phi0.7000_seed1.h5"), packing);
  EXPECT_EQ(std::distance(fs::directory_iterator(work() / "out/runs"), fs::directory_iterator()),
            2);
}

// Issue 65, class C: a sweep ended by SIGTERM (a batch system's time limit)
// or Ctrl-C said nothing. It says, in one line on stderr, that the run can
// be resumed; it still ends by the signal, with no temporary file left, and
// the same command goes on from the checkpoint.
TEST_F(MicroCli, SweepEndedByASignalSaysHowToResume) {
  const std::string entries =
      "  set volume fractions = 0.8\n  set gamma dot tildes = 3e-5\n  set packings = 1\n"
      "  set checkpoint steps = 100\n";
  parameters("s.prm", sweep_file("out", entries, 6.0));
  const fs::path checkpoint = work() / "out/runs/phi0.8000_gt3.000e-05_seed1.checkpoint.h5";
  softglass::testing::BackgroundTool sweep(
      SOFTGLASS_MICRO_EXECUTABLE, "--threads 1 sweep s.prm --quiet", work(), dir_ / "signalled");
  ASSERT_TRUE(softglass::testing::wait_until([&] { return fs::exists(checkpoint); }, 120));
  sweep.signal(SIGTERM);
  const auto ended = sweep.wait();
  EXPECT_EQ(ended.signal, SIGTERM) << "exit code " << ended.code << ": " << ended.err;
  EXPECT_EQ(ended.err,
            "micro sweep: interrupted; run the same command again to resume (finished cases are "
            "kept)\n");
  for (const auto& entry : fs::recursive_directory_iterator(work() / "out"))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  ASSERT_FALSE(fs::exists(work() / "out/runs/phi0.8000_gt3.000e-05_seed1.h5"))
      << "ended too late: the case had finished";
  const Outcome resumed = micro("--threads 1 sweep s.prm --quiet");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resumed from its checkpoint"), std::string::npos) << resumed.out;
}

// The run is checkpointed every 100 accepted steps; the first sweep is killed
// (SIGKILL: no chance to clean up) once a checkpoint exists, the rerun resumes
// it, and the tables must be those of the uninterrupted sweep to the last digit.
TEST_F(MicroCli, SweepKilledMidCaseResumesToTheUninterruptedTable) {
  const std::string entries =
      "  set volume fractions = 0.8\n  set gamma dot tildes = 3e-5\n  set packings = 1\n"
      "  set checkpoint steps = 100\n";
  parameters("reference.prm", sweep_file("reference", entries, 6.0));
  parameters("killed.prm", sweep_file("killed", entries, 6.0));
  ASSERT_EQ(micro("--threads 1 sweep reference.prm --quiet").code, 0);

  const fs::path checkpoint = work() / "killed/runs/phi0.8000_gt3.000e-05_seed1.checkpoint.h5";
  kill_after_checkpoint(work(), "--threads 1 sweep killed.prm --quiet", checkpoint,
                        work() / "killed/runs/phi0.8000_gt3.000e-05_seed1.h5");
  if (HasFatalFailure()) return;

  // Under another integrator tolerance the checkpoint is refused, and kept:
  // its steps were taken under the first. The case fails as a case does in a
  // whole sweep: logged, the table without it, exit code 1.
  parameters("changed.prm", sweep_file("killed", entries, 6.0) +
                                "subsection integrator\n  set tolerance = 1e-3\nend\n");
  const Outcome refused = micro("--threads 1 sweep changed.prm --quiet");
  EXPECT_EQ(refused.code, 1);
  const std::string said = refused.out + refused.err;
  for (const std::string& named :
       {std::string("is the checkpoint of another computation"), checkpoint.filename().string(),
        std::string("'integrator/tolerance = 0'"), std::string("'integrator/tolerance = 1e-3'")})
    EXPECT_NE(said.find(named), std::string::npos) << named << " in " << said;
  EXPECT_TRUE(fs::exists(checkpoint));

  const Outcome resumed = micro("--threads 1 sweep killed.prm --quiet");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("resumed from its checkpoint"), std::string::npos) << resumed.out;
  EXPECT_FALSE(fs::exists(checkpoint)) << "a finished case removes its checkpoint";
  EXPECT_EQ(table_data(work() / "killed/flow_curve.csv"),
            table_data(work() / "reference/flow_curve.csv"));
  EXPECT_EQ(table_data(work() / "killed/flow_curve_packings.csv"),
            table_data(work() / "reference/flow_curve_packings.csv"));
  // The record's times count the part before the kill: the checkpoint holds it.
  const H5File record = H5File::open(work() / "killed/runs/phi0.8000_gt3.000e-05_seed1.h5");
  const H5Group timings = record.root().group("timings");
  EXPECT_GT(timings.read_scalar("resumed"), 0.0);
  EXPECT_GT(timings.read_scalar("shear"), timings.read_scalar("resumed"));
  EXPECT_GE(timings.read_scalar("total"), timings.read_scalar("shear"));
  // The log line gives the same whole-run time, not only the resumed part.
  std::smatch logged;
  ASSERT_TRUE(std::regex_search(
      resumed.out, logged,
      std::regex(R"(([0-9.]+) s, resumed from its checkpoint \(([0-9.]+) s of it before\))")))
      << resumed.out;
  EXPECT_NEAR(std::stod(logged[1]), timings.read_scalar("total"), 0.051);  // printed to 0.1 s
  EXPECT_NEAR(std::stod(logged[2]), timings.read_scalar("resumed"), 0.051);
}

}  // namespace
}  // namespace softglass::micro
