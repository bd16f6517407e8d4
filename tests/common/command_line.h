// Driving a built tool as a user would: run it in a folder, capture its exit
// code, stdout and stderr (into files of their own, so that a check for
// leftover files in the working folder sees only what the tool wrote).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/common/test_files.h"

namespace softglass::testing {

struct Outcome {
  int code;
  std::string out, err;
};

/// `executable arguments` run in `directory`; stdout and stderr go through
/// files in `capture`.
inline Outcome run_tool(const std::filesystem::path& executable, const std::string& arguments,
                        const std::filesystem::path& directory, const std::filesystem::path& capture) {
  std::filesystem::create_directories(capture);
  const std::filesystem::path out = capture / "stdout.txt", err = capture / "stderr.txt";
  const std::string command = "cd '" + directory.string() + "' && '" + executable.string() + "' " +
                              arguments + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status)) << command;
  return {WEXITSTATUS(status), read_text(out), read_text(err)};
}

/// As run_tool, with every file the tool writes limited to `kilobytes`
/// (SIGXFSZ ignored): a write beyond fails (EFBIG) as on a full disk.
inline Outcome run_tool_on_full_disk(const std::filesystem::path& executable,
                                     const std::string& arguments,
                                     const std::filesystem::path& directory,
                                     const std::filesystem::path& capture, int kilobytes) {
  return run_tool("/bin/bash",
                  "-c \"trap '' XFSZ; ulimit -f " + std::to_string(kilobytes) + "; exec '" +
                      executable.string() + "' " + arguments + "\"",
                  directory, capture);
}

/// Names of the entries of `directory`, sorted.
inline std::vector<std::string> file_names(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace softglass::testing
