// The run identity (micro/input/finished_work.h), tried on every entry: a
// finished file is reused only for the same computation. For each entry of a
// complete run listing and of a sweep case's, the stored text is changed in
// that entry alone; the check must refuse it naming the entry — except for
// the entries that only say where files are, and the model preset, which only
// sets entries compared themselves. Exhaustive rather than random: a listing
// has a few dozen entries (issue 19, class 1: a changed contact law, max
// strain or N was reused in silence).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/errors.h"
#include "common/h5_file.h"
#include "common/parameter_input.h"
#include "micro/input/finished_work.h"
#include "fuzz_check.h"
#include "micro/input/parameter_file.h"
#include "tests/common/test_files.h"

namespace softglass::micro {
namespace {

using softglass::testing::TemporaryDirectory;
using softglass::testing::fuzz::count_input;
using softglass::testing::write_text;

// A stand-in for a finished run: the one dataset the check reads.
void write_finished(const std::filesystem::path& path, const std::string& parameters) {
  H5File file = H5File::create(path);
  file.root().write_string("parameters", parameters);
  file.close();
}

// `text` with the value of the entry on line `line` (1-based) replaced.
std::string with_value(const std::string& text, std::size_t line, const std::string& value) {
  std::size_t begin = 0;
  for (std::size_t k = 1; k < line; ++k) begin = text.find('\n', begin) + 1;
  const std::size_t equals = text.find('=', begin), end = text.find('\n', begin);
  return text.substr(0, equals + 1) + " " + value + text.substr(end);
}

bool only_says_where_files_are(const SetEntry& e) {
  return e.name == "file" || e.name == "input file" || e.key() == "model/preset";
}

void expect_every_entry_checked(const std::string& listing, const std::filesystem::path& dir) {
  const std::filesystem::path run = dir / "run.h5";
  write_finished(run, listing);
  EXPECT_NO_THROW(require_same_computation(run, listing));
  const std::vector<SetEntry> entries = entries_set_in(listing, "listing");
  ASSERT_GT(entries.size(), 40u) << "a complete listing";
  for (const SetEntry& e : entries) {
    const std::string changed = with_value(listing, e.line, e.value + "7");
    write_finished(run, changed);
    if (only_says_where_files_are(e)) {
      EXPECT_NO_THROW(require_same_computation(run, listing)) << e.key();
      count_input(true);
      continue;
    }
    try {
      require_same_computation(run, listing);
      count_input(true);
      ADD_FAILURE() << "a run with another " << e.key() << " was accepted";
    } catch (const InputError& error) {
      count_input(false);
      EXPECT_NE(std::string(error.what()).find(e.key() + " = " + e.value + "7"),
                std::string::npos)
          << error.what();
    }
  }
  // The documentation comments change with the software, not the computation.
  std::string reworded = listing;
  for (std::size_t at = 0; (at = reworded.find("  # ", at)) != std::string::npos; at += 4)
    reworded.insert(at + 4, "(reworded) ");
  write_finished(run, reworded);
  EXPECT_NO_THROW(require_same_computation(run, listing));
}

TEST(RunIdentity, EveryEntryButPathsDecidesWhetherARunIsReused) {
  TemporaryDirectory dir;
  write_text(dir / "run.prm", softglass::testing::read_text(
                                  std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" /
                                  "run_phi080_1e-4.prm"));
  expect_every_entry_checked(read_parameter_file(dir / "run.prm").text, dir.path());
}

TEST(RunIdentity, EveryEntryOfASweepCaseDecidesWhetherItIsReused) {
  TemporaryDirectory dir;
  write_text(dir / "sweep.prm", "subsection model\n  set preset = softglass\nend\n"
                                "subsection sweep\n  set preset = fast\nend\n");
  const SweepParameters sweep = read_sweep_file(dir / "sweep.prm");
  const MicroParameters one_case = case_parameters(
      sweep.base, {.particles = 250, .volume_fraction = 0.8, .gamma_tilde = 1e-6, .seed = 3,
                   .run = std::nullopt, .packing_input = "packing.h5", .output = "case.h5"});
  expect_every_entry_checked(one_case.text, dir.path());
}

}  // namespace
}  // namespace softglass::micro
