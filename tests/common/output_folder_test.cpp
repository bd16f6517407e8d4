// OutputFolder (common/output_folder.h): a result folder is made ready before
// any work, or refused with one line naming the path and the reason; the
// folders it made are gone again when nothing was written into them.
#include "common/output_folder.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/errors.h"
#include "tests/common/test_files.h"

namespace softglass {
namespace {

namespace fs = std::filesystem;
using testing::TemporaryDirectory;
using testing::write_text;

// The message of the InputError `make` throws, or "" when it throws none.
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(OutputFolder, MakesTheMissingFoldersAndRemovesThemWhenNothingWasWritten) {
  TemporaryDirectory dir;
  const fs::path folder = dir / "a" / "b" / "c";
  {
    const OutputFolder made(folder);
    EXPECT_TRUE(fs::is_directory(folder));
    EXPECT_EQ(made.path(), folder);
  }
  EXPECT_FALSE(fs::exists(dir / "a")) << "a refused or failed command leaves no folder";
}

TEST(OutputFolder, KeepsAFolderThatHoldsAResultAndOneThatExisted) {
  TemporaryDirectory dir;
  {
    const OutputFolder made(dir / "new" / "out");
    write_text(dir / "new" / "out" / "result.csv", "x\n");
  }
  EXPECT_TRUE(fs::exists(dir / "new" / "out" / "result.csv"));
  fs::create_directory(dir / "old");
  { const OutputFolder existing(dir / "old/"); }
  EXPECT_TRUE(fs::is_directory(dir / "old")) << "not made here: not removed";
}

// Issue 65, class B2: these were "filesystem error: cannot create
// directories", exit code 1, after the work.
TEST(OutputFolder, RefusesAFileAFolderUnderAFileAndOneThatCannotBeCreated) {
  TemporaryDirectory dir;
  write_text(dir / "afile", "data");
  const std::string file = refusal([&] { OutputFolder f(dir / "afile"); });
  EXPECT_NE(file.find(fmt::format("'{}' is a file, not a folder", (dir / "afile").string())),
            std::string::npos)
      << file;
  const std::string under = refusal([&] { OutputFolder f(dir / "afile" / "out"); });
  EXPECT_NE(under.find(fmt::format("cannot be created: '{}' is a file", (dir / "afile").string())),
            std::string::npos)
      << under;
  // /proc takes no new folders.
  const std::string proc = refusal([] { OutputFolder f("/proc/softglass-output"); });
  EXPECT_NE(proc.find("'/proc/softglass-output' cannot be created: "), std::string::npos) << proc;
  EXPECT_EQ(testing::read_text(dir / "afile"), "data");
}

// Needs a user whom permissions bind: root writes anyway, so it is skipped there.
TEST(OutputFolder, RefusesAFolderItCannotWriteIn) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into a read-only folder";
  TemporaryDirectory dir;
  fs::create_directory(dir / "locked");
  fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  const std::string locked = refusal([&] { OutputFolder f(dir / "locked"); });
  EXPECT_NE(locked.find("is not writable: Permission denied"), std::string::npos) << locked;
  const std::string inside = refusal([&] { OutputFolder f(dir / "locked" / "out"); });
  EXPECT_NE(inside.find("cannot be created: Permission denied"), std::string::npos) << inside;
  fs::permissions(dir / "locked", fs::perms::owner_all);
}

}  // namespace
}  // namespace softglass
