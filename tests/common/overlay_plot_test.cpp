// write_overlay_png and plot_outcome (common/overlay_plot.h): a missing or
// failing gnuplot is told apart from a plot that could not be stored (issue
// 65, class B4: a full disk was reported as "gnuplot is missing or failed"
// and the plot dropped with exit code 0). The shell statuses are real ones,
// and /dev/full is a file every write to which fails as on a full disk.
#include "common/overlay_plot.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/common/test_files.h"

namespace softglass {
namespace {

namespace fs = std::filesystem;
using Kind = PlotOutcome::Kind;
using testing::TemporaryDirectory;
using testing::write_text;

// The wait status of a shell that exits with `code`.
int shell_status(int code) {
  return std::system(("exit " + std::to_string(code)).c_str());
}

const std::string kCompletePng =
    std::string("\x89PNG\r\n\x1a\n", 8) + "pixels" + std::string("IEND\xae\x42\x60\x82", 8);

TEST(PlotOutcome, AShellThatFindsNoGnuplotIsAMissingGnuplot) {
  TemporaryDirectory dir;
  write_text(dir / "plot.png", "");
  const PlotOutcome o = plot_outcome(shell_status(127), dir / "plot.png");
  EXPECT_EQ(o.kind, Kind::no_gnuplot);
  EXPECT_EQ(o.reason, "gnuplot is not installed");
}

TEST(PlotOutcome, ACompletePngIsWritten) {
  TemporaryDirectory dir;
  write_text(dir / "plot.png", kCompletePng);
  EXPECT_TRUE(plot_outcome(shell_status(0), dir / "plot.png").written());
  EXPECT_EQ(testing::read_text(dir / "plot.png"), kCompletePng) << "a written plot is not probed";
}

TEST(PlotOutcome, AFailedGnuplotIsAFailedGnuplotWhereTheFolderTakesData) {
  TemporaryDirectory dir;
  write_text(dir / "plot.png", "");
  const PlotOutcome o = plot_outcome(shell_status(1), dir / "plot.png");
  EXPECT_EQ(o.kind, Kind::gnuplot_failed);
  EXPECT_EQ(o.reason, "gnuplot failed (exit status 1)");
  EXPECT_EQ(fs::file_size(dir / "plot.png"), 0u) << "the probe leaves nothing behind";
}

TEST(PlotOutcome, APlotThatCannotBeStoredIsAWriteFailureWithTheSystemsReason) {
  for (const int code : {0, 1}) {
    const PlotOutcome o = plot_outcome(shell_status(code), "/dev/full");
    EXPECT_EQ(o.kind, Kind::write_failed) << "gnuplot exit status " << code;
    EXPECT_EQ(o.reason, "No space left on device");
  }
}

// gnuplot does not check its writes: a truncated PNG after a success is a
// failed write even when the folder takes data again by the time it is looked at.
TEST(PlotOutcome, AnIncompletePngAfterSuccessIsAWriteFailure) {
  TemporaryDirectory dir;
  write_text(dir / "plot.png", kCompletePng.substr(0, 12));
  const PlotOutcome o = plot_outcome(shell_status(0), dir / "plot.png");
  EXPECT_EQ(o.kind, Kind::write_failed);
  EXPECT_NE(o.reason.find("incomplete"), std::string::npos) << o.reason;
}

const OverlayPlot kPlot{
    .title = "test",
    .panels = {compared_panel("y [1]", "x [1]", {1.0, 2.0, 4.0}, {1.0, 2.0, 3.0}, {1.1, 2.1, 2.9}),
               compared_panel("z [Pa]", "w [1/s]", {0.1, 1.0}, {5.0, 6.0}, {5.5, 6.5})}};

TEST(OverlayPlot, WithoutGnuplotOnThePathTheOutcomeSaysSo) {
  TemporaryDirectory dir;
  write_text(dir / "plot.png", "");
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", dir.path().c_str(), 1);
  const PlotOutcome o = write_overlay_png(kPlot, dir / "plot.png");
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(o.kind, Kind::no_gnuplot) << o.reason;
}

TEST(OverlayPlot, GnuplotWritesACompletePng) {
  if (!fs::exists("/usr/bin/gnuplot")) GTEST_SKIP() << "no gnuplot";
  TemporaryDirectory dir;
  write_text(dir / "plot.png", "");
  const PlotOutcome o = write_overlay_png(kPlot, dir / "plot.png");
  EXPECT_TRUE(o.written()) << o.reason;
  EXPECT_GT(fs::file_size(dir / "plot.png"), 1000u);
}

}  // namespace
}  // namespace softglass
