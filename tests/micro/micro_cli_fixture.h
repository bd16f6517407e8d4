// The `micro` executable driven as a user would: a fixture that runs it in a
// fresh temporary directory. `work/` holds parameter and result files,
// `capture/` the command's stdout and stderr (kept apart so that a check for
// leftover temporary files sees only what micro wrote).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "micro_test_support.h"
#include "tests/common/command_line.h"

namespace softglass::micro {

namespace fs = std::filesystem;

using softglass::testing::Outcome;

class MicroCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(work());
  }

  fs::path work() const { return dir_ / "work"; }

  // Runs `micro <arguments>` in work/ and returns its exit code and output.
  Outcome micro(const std::string& arguments) const {
    return softglass::testing::run_tool(SOFTGLASS_MICRO_EXECUTABLE, arguments, work(), dir_ / "capture");
  }

  // Writes `text` as work/<name> and returns the file name.
  std::string parameters(const std::string& name, const std::string& text) const {
    testing::write_text(work() / name, text);
    return name;
  }

  std::vector<std::string> files_in_work() const { return softglass::testing::file_names(work()); }

  // `micro <subcommand> bad.prm --quiet` on `text` is refused before any work:
  // exit 2, an error naming `words`, and no work/out folder.
  void expect_refused(const std::string& subcommand, const std::string& text,
                      const std::string& words) const {
    parameters("bad.prm", text);
    const Outcome o = micro(subcommand + " bad.prm --quiet");
    EXPECT_EQ(o.code, 2) << text << o.out << o.err;
    EXPECT_NE(o.err.find(words), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(work() / "out")) << "nothing written for: " << words;
  }

  testing::TemporaryDirectory dir_;
};

}  // namespace softglass::micro
