// AtomicOutput: a result file appears whole on commit() or not at all, and an
// existing result is only replaced when asked for.
#include "common/atomic_output.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.h"

namespace softglass {
namespace {

namespace fs = std::filesystem;

// Each test works in a directory of its own, removed afterwards.
class AtomicOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("softglass-" + std::string(test->test_suite_name()) + "-" +
                                        test->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path result() const { return dir_ / "result.h5"; }

  fs::path dir_;
};

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The names in `dir`, sorted.
std::vector<std::string> file_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

bool directory_is_empty(const fs::path& dir) {
  return fs::directory_iterator(dir) == fs::directory_iterator();
}

// The parent's side of a forked child that writes one byte to `ready` once it
// holds what the test examines: waits for that byte.
void await_ready(int ready[2]) {
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
}

// Sends `signal` to `child` and expects it to end by that signal.
void expect_ended_by(pid_t child, int signal) {
  ASSERT_EQ(::kill(child, signal), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << signal;
  EXPECT_EQ(WTERMSIG(status), signal);
}

TEST_F(AtomicOutputTest, CommitMovesTheTemporaryFileOntoTheFinalPath) {
  AtomicOutput output(result(), false);
  EXPECT_EQ(output.final_path(), result());
  EXPECT_NE(output.temporary_path(), result());
  EXPECT_EQ(output.temporary_path().parent_path(), dir_);  // same file system: rename is atomic

  write_text(output.temporary_path(), "complete");
  EXPECT_FALSE(fs::exists(result()));
  output.commit();

  EXPECT_EQ(read_text(result()), "complete");
  EXPECT_FALSE(fs::exists(output.temporary_path()));
}

TEST_F(AtomicOutputTest, DestructionWithoutCommitLeavesNothing) {
  {
    AtomicOutput output(result(), false);
    write_text(output.temporary_path(), "partial");
  }
  EXPECT_TRUE(directory_is_empty(dir_));
}

TEST_F(AtomicOutputTest, DestructionWithoutCommitKeepsTheEarlierResult) {
  write_text(result(), "earlier");
  fs::path temporary;
  {
    AtomicOutput output(result(), true);
    temporary = output.temporary_path();
    write_text(temporary, "partial");
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(read_text(result()), "earlier");
}

TEST_F(AtomicOutputTest, RefusesAnExistingFileWithoutOverwrite) {
  write_text(result(), "earlier");
  try {
    AtomicOutput output(result(), false);
    FAIL() << "no OutputExistsError";
  } catch (const OutputExistsError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(result().string()), std::string::npos) << message;
    EXPECT_NE(message.find("--force"), std::string::npos) << message;
  }
  EXPECT_EQ(read_text(result()), "earlier");
}

TEST_F(AtomicOutputTest, OverwriteReplacesTheEarlierResultOnCommit) {
  write_text(result(), "earlier");
  AtomicOutput output(result(), true);
  write_text(output.temporary_path(), "later");
  EXPECT_EQ(read_text(result()), "earlier");  // untouched until commit
  output.commit();
  EXPECT_EQ(read_text(result()), "later");
  EXPECT_FALSE(fs::exists(output.temporary_path()));
}

TEST_F(AtomicOutputTest, AMissingDirectoryIsAnInputError) {
  const auto missing = dir_ / "missing";
  try {
    AtomicOutput output(missing / "result.h5", false);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
  }
}

TEST_F(AtomicOutputTest, AnEmptyPathIsAnInputError) {
  EXPECT_THROW(AtomicOutput(fs::path(), false), InputError);
}

// An output that cannot be written is refused when the output is claimed,
// before any work (issue 19, class 6): a directory in place of the file
// (with --force too), and a folder without write permission.
TEST_F(AtomicOutputTest, ADirectoryInPlaceOfTheOutputIsRefusedBeforeTheWork) {
  fs::create_directory(dir_ / "taken");
  try {
    AtomicOutput output(dir_ / "taken", true);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_ / "taken"));
}

// Needs a user whom permissions bind: root writes anyway, so it is skipped there.
TEST_F(AtomicOutputTest, AReadOnlyFolderIsRefusedBeforeTheWork) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into a read-only folder";
  fs::create_directory(dir_ / "locked");
  fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  try {
    AtomicOutput output(dir_ / "locked" / "result.h5", false);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot write in output directory"),
              std::string::npos)
        << error.what();
  }
  fs::permissions(dir_ / "locked", fs::perms::owner_all);
}

TEST_F(AtomicOutputTest, TheTemporaryFileExistsFromTheStart) {
  AtomicOutput output(result(), false);
  EXPECT_TRUE(fs::exists(output.temporary_path())) << "claimed before the work";
}

// A process killed while writing leaves its temporary file; the next process
// that completes the same output removes it, and keeps a live process's one
// (PID 1 is always alive) and any other file.
TEST_F(AtomicOutputTest, TheNextCompletedOutputRemovesTheTemporariesOfKilledProcesses) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    AtomicOutput output(result(), false);
    std::ofstream(output.temporary_path()) << "half";
    ::raise(SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  const fs::path killed = result().string() + ".tmp" + std::to_string(child);
  ASSERT_TRUE(fs::exists(killed)) << "a killed process cannot clean up";
  const fs::path alive = result().string() + ".tmp1";
  const fs::path other = result().string() + ".tmp-notes";
  write_text(alive, "live");
  write_text(other, "mine");

  AtomicOutput output(result(), false);
  write_text(output.temporary_path(), "complete");
  output.commit();
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_EQ(read_text(result()), "complete");
}

// Ctrl-C, a batch system's SIGTERM at its time limit, a closed terminal: the
// process removes what it was writing, earlier results stay, and it still
// ends by the signal (the shell and the batch system see 130, 143, 129).
TEST_F(AtomicOutputTest, ATerminatingSignalRemovesTheTemporariesAndStillEndsTheProcess) {
  write_text(result(), "earlier");
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      AtomicOutput first(result(), true);
      AtomicOutput second(dir_ / "table.csv", false);
      std::ofstream(first.temporary_path()) << "half";
      const char byte = 1;
      if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
      for (;;) ::pause();
    }
    await_ready(ready);
    const fs::path temporary = result().string() + ".tmp" + std::to_string(child);
    ASSERT_TRUE(fs::exists(temporary));
    expect_ended_by(child, signal);
    EXPECT_FALSE(fs::exists(temporary)) << "signal " << signal;
    EXPECT_FALSE(fs::exists(dir_ / ("table.csv.tmp" + std::to_string(child))));
    EXPECT_EQ(read_text(result()), "earlier");
  }
}

// One result is several files (a law and its tables, a sweep's CSV and HDF5
// tables): a signal that arrives while they are put in place must not leave
// some new and some old. The child renames 200 files as a set right after
// telling the parent, which sends SIGTERM at once, inside the renames; with
// the signals not held back the folder was left mixed.
TEST_F(AtomicOutputTest, ASignalDuringTheCommitOfASetLeavesItWholeOldOrWholeNew) {
  constexpr int kFiles = 200;  // within the slots a signal handler cleans
  const auto name = [&](int k) { return dir_ / ("part" + std::to_string(k) + ".csv"); };
  for (int trial = 0; trial < 10; ++trial) {
    for (int k = 0; k < kFiles; ++k) write_text(name(k), "old");
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::vector<std::unique_ptr<AtomicOutput>> outputs;
      std::vector<AtomicOutput*> set;
      for (int k = 0; k < kFiles; ++k) {
        outputs.push_back(std::make_unique<AtomicOutput>(name(k), true));
        std::ofstream(outputs.back()->temporary_path()) << "new";
        set.push_back(outputs.back().get());
      }
      const char byte = 1;
      if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
      AtomicOutput::commit_together(set);
      for (;;) ::pause();  // the held signal ends it here at the latest
    }
    await_ready(ready);
    expect_ended_by(child, SIGTERM);
    int renewed = 0;
    for (int k = 0; k < kFiles; ++k) renewed += read_text(name(k)) == "new" ? 1 : 0;
    EXPECT_TRUE(renewed == 0 || renewed == kFiles) << renewed << " of " << kFiles << " new";
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), kFiles)
        << "temporaries left";
  }
}

// Writes `text` to `path` through an AtomicOutput of a process of its own
// (the temporary's name holds the PID: one process claims a path once), as
// another run of a command would; whether its commit succeeded.
bool commit_in_another_process(const fs::path& path, const std::string& text, bool overwrite) {
  const pid_t child = ::fork();
  if (child == 0) {
    try {
      AtomicOutput output(path, overwrite);
      std::ofstream(output.temporary_path()) << text;
      output.commit();
    } catch (...) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  int status = 0;
  return child > 0 && ::waitpid(child, &status, 0) == child && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

// Issue 65, class A: two processes writing one output without --force both
// claimed it at their start, when it did not exist yet, and the later commit
// silently replaced the earlier result. The later commit is refused now, and
// the earlier result kept.
TEST_F(AtomicOutputTest, WithoutOverwriteTheLaterOfTwoWritersIsRefusedAtItsCommit) {
  fs::path temporary;
  {
    AtomicOutput later(result(), false);
    temporary = later.temporary_path();
    write_text(temporary, "later");
    ASSERT_TRUE(commit_in_another_process(result(), "earlier", false));
    try {
      later.commit();
      FAIL() << "no OutputExistsError";
    } catch (const OutputExistsError& error) {
      const std::string message = error.what();
      for (const std::string& part : {result().string(), std::string("another process"),
                                      std::string("is kept"), std::string("--force")})
        EXPECT_NE(message.find(part), std::string::npos) << part << " in " << message;
    }
    EXPECT_EQ(read_text(result()), "earlier");
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(file_names(dir_), std::vector<std::string>{"result.h5"});
}

// With overwrite (--force) the later writer replaces the earlier one's file,
// as it would replace any older result.
TEST_F(AtomicOutputTest, WithOverwriteTheLaterOfTwoWritersReplacesTheEarlier) {
  AtomicOutput later(result(), true);
  write_text(later.temporary_path(), "later");
  ASSERT_TRUE(commit_in_another_process(result(), "earlier", false));
  later.commit();
  EXPECT_EQ(read_text(result()), "later");
}

// A set is one result: when its last file turns out to be another process's,
// the files this commit had already put in place are taken back, so that
// neither set is left mixed; the other process's file stays.
TEST_F(AtomicOutputTest, ASetThatMeetsAnotherWritersFileTakesItsFilesBack) {
  const fs::path law = dir_ / "law.prm", phi = dir_ / "law_phi.csv",
                 points = dir_ / "law_points.csv";
  {
    AtomicOutput law_out(law, false), phi_out(phi, false), points_out(points, false);
    for (AtomicOutput* out : {&law_out, &phi_out, &points_out})
      write_text(out->temporary_path(), "later");
    ASSERT_TRUE(commit_in_another_process(points, "earlier", false));
    EXPECT_THROW(AtomicOutput::commit_together({&law_out, &phi_out, &points_out}),
                 OutputExistsError);
    EXPECT_FALSE(fs::exists(law));
    EXPECT_FALSE(fs::exists(phi));
    EXPECT_EQ(read_text(points), "earlier");
  }
  EXPECT_EQ(file_names(dir_), std::vector<std::string>{"law_points.csv"}) << "temporaries left";
}

// A resumable command registers how to resume; a terminating signal prints
// that line on stderr, and the process still ends by the signal with its
// temporaries removed.
TEST_F(AtomicOutputTest, ATerminatingSignalPrintsTheRegisteredNotice) {
  const fs::path log = dir_ / "stderr.txt";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || ::dup2(fd, STDERR_FILENO) < 0) ::_exit(3);
    set_interruption_notice("tool: interrupted; run the same command again to resume");
    AtomicOutput output(result(), false);
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
    for (;;) ::pause();
  }
  await_ready(ready);
  expect_ended_by(child, SIGTERM);
  EXPECT_EQ(read_text(log), "tool: interrupted; run the same command again to resume\n");
  EXPECT_EQ(file_names(dir_), std::vector<std::string>{"stderr.txt"}) << "temporary left";
}

}  // namespace
}  // namespace softglass
