// The `micro` executable driven as a user would: a fixture that runs it in a
// fresh temporary directory. `work/` holds parameter and result files,
// `capture/` the command's stdout and stderr (kept apart so that a check for
// leftover temporary files sees only what micro wrote).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "micro_test_support.h"

namespace softglass::micro {

namespace fs = std::filesystem;

struct Outcome {
  int code;
  std::string out, err;
};

class MicroCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(work());
    fs::create_directories(dir_ / "capture");
  }

  fs::path work() const { return dir_ / "work"; }

  // Runs `micro <arguments>` in work/ and returns its exit code and output.
  Outcome micro(const std::string& arguments) const {
    const fs::path out = dir_ / "capture" / "stdout.txt", err = dir_ / "capture" / "stderr.txt";
    const std::string command = "cd '" + work().string() +
                                "' && '" SOFTGLASS_MICRO_EXECUTABLE "' " + arguments + " > '" +
                                out.string() + "' 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status)) << command;
    return {WEXITSTATUS(status), testing::read_text(out), testing::read_text(err)};
  }

  // Writes `text` as work/<name> and returns the file name.
  std::string parameters(const std::string& name, const std::string& text) const {
    testing::write_text(work() / name, text);
    return name;
  }

  std::vector<std::string> files_in_work() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(work()))
      names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

  testing::TemporaryDirectory dir_;
};

}  // namespace softglass::micro
