// Driving a built tool as a user would: run it in a folder, capture its exit
// code, stdout and stderr (into files of their own, so that a check for
// leftover files in the working folder sees only what the tool wrote).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
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

/// A tool started in the background as a user would from a shell (its own
/// process: the shell execs it), its stdout and stderr into files of
/// `capture`; it can be sent signals (SIGSTOP holds it between two steps,
/// SIGTERM ends it as a batch system would) and is waited for. Ended with
/// SIGKILL if the test leaves it running.
class BackgroundTool {
 public:
  struct Ended {
    int code = -1;   // the exit code, or -1 when a signal ended it
    int signal = 0;  // the signal that ended it, or 0
    std::string out, err;
  };

  BackgroundTool(const std::filesystem::path& executable, const std::string& arguments,
                 const std::filesystem::path& directory, const std::filesystem::path& capture)
      : out_(capture / "stdout.txt"), err_(capture / "stderr.txt") {
    std::filesystem::create_directories(capture);
    const std::string command = "exec '" + executable.string() + "' " + arguments + " > '" +
                                out_.string() + "' 2> '" + err_.string() + "'";
    pid_ = ::fork();
    if (pid_ == 0) {
      if (::chdir(directory.c_str()) != 0) ::_exit(127);
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    EXPECT_GT(pid_, 0) << "fork";
  }
  ~BackgroundTool() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  BackgroundTool(const BackgroundTool&) = delete;
  BackgroundTool& operator=(const BackgroundTool&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int number) const { EXPECT_EQ(::kill(pid_, number), 0) << "signal " << number; }
  Ended wait() {
    Ended ended;
    int status = 0;
    if (pid_ > 0 && ::waitpid(pid_, &status, 0) == pid_) {
      if (WIFEXITED(status)) ended.code = WEXITSTATUS(status);
      if (WIFSIGNALED(status)) ended.signal = WTERMSIG(status);
    }
    pid_ = -1;
    ended.out = read_text(out_);
    ended.err = read_text(err_);
    return ended;
  }

 private:
  std::filesystem::path out_, err_;
  pid_t pid_ = -1;
};

/// Polls `condition` every millisecond for at most `seconds`; whether it held.
inline bool wait_until(const std::function<bool()>& condition, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
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
