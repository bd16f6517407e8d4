// The `micro` command line, driven as a user would: exit codes (common/errors.h:
// 0 ok, 2 bad input, 3 output exists), error messages that name the offending
// parameter and its allowed range, the template, and result files that appear
// whole or not at all.
//
// Every test works in a fresh temporary directory: `work/` holds parameter and
// result files, `capture/` the command's stdout and stderr (kept apart so that
// the check for leftover temporary files sees only what micro wrote).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "micro/contact/contact_law.h"
#include "micro/io/run_file.h"
#include "micro_cli_fixture.h"

namespace softglass::micro {
namespace {

// A small, fast packing: N = 200 needs a skin below ~0.6 for the neighbour grid.
const std::string kTiny =
    "subsection particles\n"
    "  set number          = 200\n"
    "  set volume fraction = 0.7\n"
    "end\n"
    "subsection neighbours\n"
    "  set skin = 0.3\n"
    "end\n"
    "subsection output\n"
    "  set file = tiny.h5\n"
    "end\n";

// The tiny parameter file with the entry `name` of `subsection` set to `value`:
// its line replaced where the file sets it already (an entry is set once per
// file), a subsection added otherwise.
std::string tiny_with(const std::string& subsection, const std::string& name,
                      const std::string& value) {
  const std::regex existing("(subsection " + subsection + "\n(?:  set [^\n]*\n)*?  set " + name +
                            " +=) [^\n]*");
  if (std::regex_search(kTiny, existing)) return std::regex_replace(kTiny, existing, "$1 " + value);
  return kTiny + "subsection " + subsection + "\n  set " + name + " = " + value + "\nend\n";
}

TEST_F(MicroCli, HelpExitsZero) {
  const Outcome o = micro("--help");
  EXPECT_EQ(o.code, 0) << o.err;
  for (const char* word : {"pack", "run", "template"})
    EXPECT_NE(o.out.find(word), std::string::npos) << o.out;
}

TEST_F(MicroCli, BadCommandLinesExitTwo) {
  EXPECT_EQ(micro("").code, 2) << "a subcommand is required";
  EXPECT_EQ(micro("pack").code, 2) << "pack needs a parameter file";
  EXPECT_EQ(micro("frobnicate").code, 2);
  EXPECT_EQ(micro("--threads 0 template").code, 2);
}

TEST_F(MicroCli, MissingParameterFileExitsTwoNamingIt) {
  const Outcome o = micro("pack --quiet no_such_file.prm");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("no_such_file.prm"), std::string::npos) << o.err;
  EXPECT_TRUE(files_in_work().empty());
}

// A rejected parameter: exit code 2, and the message names the entry and (where
// there is one) what is allowed.
struct BadParameter {
  const char* what;
  std::string file;
  std::vector<std::string> message_contains;
};

TEST_F(MicroCli, EveryBadParameterIsRejectedWithExitCodeTwo) {
  const std::vector<BadParameter> cases = {
      {"unknown entry", tiny_with("particles", "colour", "red"), {"colour", "line 12 of file"}},
      {"unknown subsection", kTiny + "subsection nonsense\n  set number = 1\nend\n", {"nonsense"}},
      {"volume fraction below 0.64",
       tiny_with("particles", "volume fraction", "0.5"),
       {"volume fraction", "0.64", "0.95"}},
      {"volume fraction above 0.95",
       tiny_with("particles", "volume fraction", "0.99"),
       {"volume fraction", "0.64", "0.95"}},
      {"negative polydispersity",
       tiny_with("particles", "polydispersity", "-0.1"),
       {"polydispersity", "0.3"}},
      {"non-numeric value",
       tiny_with("particles", "volume fraction", "abc"),
       {"abc", "volume fraction", "0.64", "0.95"}},
      {"nan volume fraction",
       tiny_with("particles", "volume fraction", "nan"),
       {"volume fraction", "0.64", "0.95"}},
      {"nan polydispersity",
       tiny_with("particles", "polydispersity", "nan"),
       {"polydispersity", "0.3"}},
      {"nan shear rate",
       tiny_with("shear", "gamma dot tilde", "nan"),
       {"gamma dot tilde", "1e-14", "0.1"}},
      {"nan skin", tiny_with("neighbours", "skin", "nan"), {"skin", "0.01", "2"}},
      {"nan max strain", tiny_with("shear", "max strain", "nan"), {"max strain"}},
      {"unknown law",
       tiny_with("contact law", "law", "kelvin"),
       {"kelvin", "seth2011", "hertz", "table"}},
      {"table law without file", tiny_with("contact law", "law", "table"), {"table file"}},
      {"piecewise exponents do not match its breakpoints",
       kTiny + "subsection contact law\n  set law = piecewise\n  set piecewise exponents = 1.5, 2\n"
               "end\n",
       {"piecewise", "2 exponents for 2 breakpoints"}},
      {"piecewise exponent out of range",
       tiny_with("contact law", "piecewise exponents", "1.5, 2, 30"),
       {"piecewise exponents", "10"}},
      {"mobility factor above its range",
       tiny_with("shear", "mobility factor", "1e5"),
       {"mobility factor", "10000"}},
      {"unknown EHD velocity", tiny_with("drag", "velocity", "radial"), {"radial", "full"}},
      {"unknown Stokes reference",
       tiny_with("drag", "stokes reference", "solvent"),
       {"solvent", "affine", "neighbours"}},
      {"lagged drag with the neighbours' Stokes friction",
       kTiny + "subsection drag\n  set stokes reference = neighbours\n  set coupling = lagged\nend\n",
       {"lagged", "neighbours", "implicit"}},
      {"unknown distribution",
       tiny_with("particles", "distribution", "weibull"),
       {"weibull", "gaussian", "uniform", "lognormal", "bidisperse"}},
      {"negative number of particles", tiny_with("particles", "number", "-5"), {"number"}},
      {"shear rate out of range",
       tiny_with("shear", "gamma dot tilde", "1"),
       {"gamma dot tilde", "1e-14", "0.1"}},
      {"unknown integrator", tiny_with("integrator", "scheme", "rk4"), {"rk4", "euler"}},
  };
  int index = 0;
  for (const BadParameter& c : cases) {
    const std::string file = parameters("bad" + std::to_string(index++) + ".prm", c.file);
    const Outcome o = micro("pack --quiet " + file);
    EXPECT_EQ(o.code, 2) << c.what << "\n" << o.err;
    EXPECT_NE(o.err.find("micro: error:"), std::string::npos) << c.what << "\n" << o.err;
    for (const std::string& word : c.message_contains) {
      EXPECT_NE(o.err.find(word), std::string::npos) << c.what << ": no '" << word << "' in\n"
                                                     << o.err;
    }
    EXPECT_FALSE(fs::exists(work() / "tiny.h5")) << c.what << ": no output for bad input";
  }
}

// Files that deal.II's own reader mishandles (common/parameter_input.h): a
// file that includes itself recursed until the stack overflowed; an entry set
// twice kept the last value in silence; a UTF-8 byte-order mark was refused
// with an invisible character in the message; a directory was reported as
// missing.
TEST_F(MicroCli, IncludesByteOrderMarksAndDirectoriesAreReadAsTheUserMeantThem) {
  const Outcome loop =
      micro("pack --quiet " + parameters("loop.prm", "include loop.prm\n" + kTiny));
  EXPECT_EQ(loop.code, 2) << loop.err;
  EXPECT_NE(loop.err.find("includes nest deeper than 8"), std::string::npos) << loop.err;

  parameters("particles.prm", "subsection particles\n  set seed = 2\n  set colour = red\nend\n");
  const Outcome included =
      micro("pack --quiet " + parameters("main.prm", kTiny + "include particles.prm\n"));
  EXPECT_EQ(included.code, 2) << included.err;
  EXPECT_NE(included.err.find("line 3 of file"), std::string::npos) << "the line in the included "
                                                                       "file: " << included.err;
  EXPECT_NE(included.err.find("particles.prm"), std::string::npos) << included.err;

  fs::create_directory(work() / "folder.prm");
  const Outcome folder = micro("pack --quiet " + (work() / "folder.prm").string());
  EXPECT_EQ(folder.code, 2) << folder.err;
  EXPECT_NE(folder.err.find("is a directory"), std::string::npos) << folder.err;
  EXPECT_FALSE(fs::exists(work() / "tiny.h5"));

  // One entry set twice in one file: refused naming both lines. A file that
  // includes a base file may set one of its entries again.
  const Outcome twice = micro(
      "pack --quiet " +
      parameters("twice.prm", kTiny + "subsection particles\n  set number = 300\nend\n"));
  EXPECT_EQ(twice.code, 2) << twice.err;
  EXPECT_NE(twice.err.find("'particles/number' is set a second time in this file (first on line 2)"),
            std::string::npos) << twice.err;
  parameters("base.prm", kTiny);
  const Outcome specialised = micro(
      "pack --quiet " +
      parameters("special.prm", "include base.prm\nsubsection particles\n  set number = 250\nend\n"));
  EXPECT_EQ(specialised.code, 0) << specialised.err;
  EXPECT_EQ(read_packing(work() / "tiny.h5").particles.size(), 250u);
  fs::remove(work() / "tiny.h5");

  const Outcome marked = micro("pack --quiet " + parameters("bom.prm", "\xEF\xBB\xBF" + kTiny));
  EXPECT_EQ(marked.code, 0) << marked.err;
  EXPECT_TRUE(fs::exists(work() / "tiny.h5"));
}

TEST_F(MicroCli, TemplateDocumentsEverySubsectionAndParsesBack) {
  const Outcome o = micro("template");
  ASSERT_EQ(o.code, 0) << o.err;
  for (const char* subsection : {"particles", "packing", "contact law", "shear", "drag",
                                 "integrator", "neighbours", "output"}) {
    EXPECT_NE(o.out.find(std::string("subsection ") + subsection), std::string::npos) << subsection;
  }
  EXPECT_NE(o.out.find("Allowed:"), std::string::npos) << "entries state their ranges";

  // Shrink the template's defaults to a tiny packing, line by line, and run it.
  const std::vector<std::pair<std::string, std::string>> overrides = {
      {"number", "200"}, {"volume fraction", "0.7"}, {"skin", "0.3"}, {"file", "from_template.h5"}};
  std::istringstream in(o.out);
  std::string text, line;
  int replaced = 0;
  while (std::getline(in, line)) {
    const auto set = line.find("set ");
    if (set != std::string::npos && line.find_first_not_of(' ') == set) {
      for (const auto& [name, value] : overrides) {
        const std::string rest = line.substr(set + 4);
        if (rest.rfind(name, 0) == 0 &&
            rest.find_first_not_of(' ', name.size()) == rest.find('=')) {
          line = line.substr(0, set) + "set " + name + " = " + value;
          ++replaced;
        }
      }
    }
    text += line + "\n";
  }
  ASSERT_EQ(replaced, 4) << "each overridden entry appears once in the template";
  const Outcome pack = micro("pack --quiet " + parameters("template.prm", text));
  EXPECT_EQ(pack.code, 0) << pack.err;
  EXPECT_EQ(read_packing(work() / "from_template.h5").particles.size(), 200u);
}

TEST_F(MicroCli, PackWritesAValidFileAndNoTemporaryFile) {
  const std::string prm = parameters("tiny.prm", kTiny);
  const Outcome o = micro("pack --quiet " + prm);
  ASSERT_EQ(o.code, 0) << o.err;
  const StoredPacking p = read_packing(work() / "tiny.h5");
  EXPECT_EQ(p.particles.size(), 200u);
  EXPECT_NEAR(p.report.volume_fraction, 0.7, 1e-12);
  EXPECT_TRUE(p.report.converged);
  EXPECT_GT(p.modulus.modulus, 0.0);
  EXPECT_EQ(files_in_work(), (std::vector<std::string>{"tiny.h5", "tiny.prm"}));
  EXPECT_NE(o.out.find("tiny.h5"), std::string::npos) << "says where it wrote";
}

TEST_F(MicroCli, ExistingOutputIsKeptWithoutForceAndReplacedWithIt) {
  const std::string prm = parameters("tiny.prm", kTiny);
  const std::string original = "an earlier result, not to be lost\n";
  testing::write_text(work() / "tiny.h5", original);

  const Outcome refused = micro("pack --quiet " + prm);
  EXPECT_EQ(refused.code, 3) << refused.err;
  EXPECT_NE(refused.err.find("tiny.h5"), std::string::npos) << refused.err;
  EXPECT_EQ(testing::read_text(work() / "tiny.h5"), original);  // same bytes
  EXPECT_EQ(files_in_work(), (std::vector<std::string>{"tiny.h5", "tiny.prm"}));

  // The same through -o.
  testing::write_text(work() / "other.h5", original);
  EXPECT_EQ(micro("pack --quiet -o other.h5 " + prm).code, 3);
  EXPECT_EQ(testing::read_text(work() / "other.h5"), original);

  const Outcome forced = micro("pack --quiet --force " + prm);
  ASSERT_EQ(forced.code, 0) << forced.err;
  EXPECT_NE(testing::read_text(work() / "tiny.h5"), original);
  EXPECT_EQ(read_packing(work() / "tiny.h5").particles.size(), 200u);
  EXPECT_EQ(files_in_work(), (std::vector<std::string>{"other.h5", "tiny.h5", "tiny.prm"}));
}

TEST_F(MicroCli, RunWritesATimeSeries) {
  const std::string prm = parameters(
      "run.prm", kTiny +
                     "subsection shear\n  set gamma dot tilde = 1e-4\n  set min strain = 0.3\n"
                     "  set max strain = 0.3\n  set min stationary strain = 0.2\nend\n");
  const Outcome o = micro("run --quiet -o run.h5 " + prm);
  ASSERT_EQ(o.code, 0) << o.err;
  const TimeSeries t = read_time_series(work() / "run.h5");
  ASSERT_GT(t.size(), 20u);
  EXPECT_NEAR(t.strain.back() - t.strain.front(), 0.3, 1e-9);
  EXPECT_EQ(files_in_work(), (std::vector<std::string>{"run.h5", "run.prm"}));
}

}  // namespace
}  // namespace softglass::micro

namespace softglass::micro {
namespace {

TEST_F(MicroCli, LawCoefficientsFromTheParameterFileAreStoredWithTheRun) {
  // The coefficients of a law reach the run file, and the law rebuilt from the
  // file (as `analyze` does) is the one the run used.
  const std::string prm = parameters(
      "piecewise.prm",
      kTiny +
          "subsection contact law\n  set law = piecewise\n  set piecewise breakpoints = 0.4, 0.9\n"
          "end\nsubsection shear\n  set gamma dot tilde = 1e-4\n  set min strain = 0.4\n"
          "  set max strain = 0.4\n  set min stationary strain = 0.2\n"
          "  set snapshot interval = 0.02\nend\n");
  ASSERT_EQ(micro("run --quiet -o run.h5 " + prm).code, 0);
  const StoredSnapshots stored = read_stationary_snapshots(work() / "run.h5");
  EXPECT_EQ(stored.contact_law.name, "piecewise");
  EXPECT_EQ(stored.contact_law.coefficients.text("breakpoints"), "0.4, 0.9");
  const auto used = make_contact_law(
      {.name = "piecewise",
       .coefficients = {{"breakpoints", "0.4, 0.9"}, {"exponents", "1.5, 2, 3"}, {"C", "1"}}});
  const auto rebuilt = make_contact_law(stored.contact_law);
  for (double eps : {0.2, 0.6, 1.2}) EXPECT_EQ(rebuilt->force(eps), used->force(eps)) << eps;
}

// A full disk (a file-size limit) while the result is written: HDF5 left the
// file half-closed and crashed at exit (exit 139). Now: exit 1 naming the
// file and the reason, and no file left behind.
TEST_F(MicroCli, AFullDiskIsAnErrorNamingTheReasonNotACrash) {
  const std::string prm = parameters(
      "big.prm", "subsection particles\n  set number = 2000\n  set volume fraction = 0.7\nend\n"
                 "subsection output\n  set file = big.h5\nend\n");
  const Outcome o = softglass::testing::run_tool_on_full_disk(
      SOFTGLASS_MICRO_EXECUTABLE, "pack --quiet " + prm, work(), dir_ / "capture", 24);
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("File too large"), std::string::npos) << o.err;
  EXPECT_EQ(files_in_work(), std::vector<std::string>{"big.prm"});
}

// `micro summary` averages runs over packings: one run given twice, or a copy
// of it, would count one packing twice and shrink the error bar (issue 19,
// class 1). Refused, exit 2, naming both files.
TEST_F(MicroCli, SummaryRefusesToAverageARunWithItself) {
  const std::string prm = parameters(
      "run.prm", kTiny + "subsection shear\n  set gamma dot tilde = 1e-4\n  set min strain = 0.3\n"
                         "  set max strain = 0.3\n  set min stationary strain = 0.2\nend\n");
  ASSERT_EQ(micro("run --quiet -o run.h5 " + prm).code, 0);
  fs::copy_file(work() / "run.h5", work() / "copy.h5");
  for (const char* second : {"run.h5", "copy.h5"}) {
    const Outcome o = micro(std::string("summary run.h5 ") + second);
    EXPECT_EQ(o.code, 2) << second;
    EXPECT_NE(o.err.find("start from the same packing"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find(second), std::string::npos) << o.err;
  }
  ASSERT_EQ(micro("run --quiet -o other.h5 " +
                  parameters("other.prm", tiny_with("particles", "seed", "2") +
                                              "subsection shear\n  set gamma dot tilde = 1e-4\n"
                                              "  set min strain = 0.3\n  set max strain = 0.3\n"
                                              "  set min stationary strain = 0.2\nend\n"))
                .code,
            0);
  EXPECT_EQ(micro("summary run.h5 other.h5").code, 0) << "two packings average";
}

// Issue 65, class B3: a file of another kind given to `micro summary` got
// advice that cannot help ("rerun the case") or a guess. Each is named for
// what it is: a packing, a macro result, a table, a text file.
TEST_F(MicroCli, SummaryNamesAFileOfAnotherKindForWhatItIs) {
  ASSERT_EQ(micro("pack --quiet " + parameters("tiny.prm", kTiny)).code, 0);
  testing::write_text(work() / "table.csv", "phi [1],sigma [E*]\n0.8,1e-3\n");
  // A result of `macro run`: its root says which software wrote it.
  {
    H5File macro = H5File::create(work() / "results.h5");
    macro.root().set_attribute("software", std::string("softglass macro 1.0 (test)"));
    macro.root().create_group("results");
    macro.close();
  }
  const std::string wanted =
      "not a run file of a sheared packing (micro run, micro sweep's runs/*.h5)";
  for (const auto& [file, kind] :
       {std::pair<std::string, std::string>{"tiny.h5", "is a packing file (micro pack"},
        {"results.h5", "is a result of macro run or macro compare"},
        {"table.csv", "is a text file"},
        {"tiny.prm", "is a text file"}}) {
    const Outcome o = micro("summary " + file);
    EXPECT_EQ(o.code, 2) << file;
    EXPECT_NE(o.err.find("'" + file + "' " + kind), std::string::npos) << o.err;
    EXPECT_NE(o.err.find(wanted), std::string::npos) << o.err;
    EXPECT_EQ(o.err.find("rerun"), std::string::npos) << o.err;
  }
}

TEST_F(MicroCli, AnalyzeWritesTheStructureAndKeepsItWithoutForce) {
  // A short run stores snapshots every 0.02 strain; `analyze` adds /structure
  // and the CSV tables, refuses to replace them without --force (exit 3) and a
  // file with no snapshots (exit 2).
  const std::string prm = parameters(
      "run.prm", kTiny +
                     "subsection shear\n  set gamma dot tilde = 1e-4\n  set min strain = 0.4\n"
                     "  set max strain = 0.4\n  set min stationary strain = 0.2\n"
                     "  set snapshot interval = 0.02\nend\n");
  ASSERT_EQ(micro("run --quiet -o run.h5 " + prm).code, 0);
  const StoredSnapshots stored = read_stationary_snapshots(work() / "run.h5");
  EXPECT_GE(stored.snapshots.size(), 2u);
  EXPECT_EQ(stored.contact_law.name, "piecewise");  // the softglass preset's law

  const Outcome again = micro("analyze run.h5 --csv run");  // the run wrote /structure already
  EXPECT_EQ(again.code, 3) << again.err;
  for (const char* table : {"run_harmonics.csv", "run_map.csv", "run_summary.csv"}) {
    EXPECT_FALSE(fs::exists(work() / table)) << table << ": refused, so nothing is written";
  }
  const Outcome forced = micro("analyze run.h5 --csv run --force --bin-width 0.01");
  ASSERT_EQ(forced.code, 0) << forced.err;
  for (const char* table : {"run_harmonics.csv", "run_map.csv", "run_summary.csv"}) {
    EXPECT_TRUE(fs::exists(work() / table)) << table;
  }
  EXPECT_EQ(micro("analyze run.h5 --csv run").code, 3);  // CSV files exist now too

  ASSERT_EQ(micro("pack --quiet " + parameters("tiny.prm", kTiny)).code, 0);
  const Outcome none = micro("analyze tiny.h5");
  EXPECT_EQ(none.code, 2) << none.err;
  EXPECT_NE(none.err.find("no stored configurations"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace softglass::micro
