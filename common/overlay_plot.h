// A PNG of predicted against measured curves (gnuplot, from Debian's
// gnuplot-nox), for `macro compare` and `bridge amplitude-sweep`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace softglass {

/// A curve of a panel: measured points, or a predicted line.
struct PlotCurve {
  std::string title;  // its legend entry
  std::vector<double> x, y;
  bool line = false;  // a prediction (a line) or a measurement (points)
  int colour = 0;     // its index in the palette: one colour per quantity
};

/// One panel: curves on log-log axes above the relative errors
/// predicted/measured − 1 [%] at the compared points.
struct OverlayPanel {
  std::string quantity;  // axis label, with its unit: "torque [N m]"
  std::string abscissa;  // axis label, with its unit: "shear rate [1/s]"
  std::vector<PlotCurve> curves, errors;
};

/// The panel of one measured and one predicted series at the same points.
OverlayPanel compared_panel(std::string quantity, std::string abscissa,
                            const std::vector<double>& x, const std::vector<double>& measured,
                            const std::vector<double>& predicted);

/// The relative errors predicted/measured − 1 [%] of a quantity as a curve.
PlotCurve relative_errors(std::string title, const std::vector<double>& x,
                          const std::vector<double>& measured, const std::vector<double>& predicted,
                          int colour);

/// Panels side by side: a rheologist's axes (stress against shear rate)
/// beside the instrument's (torque against angular velocity).
struct OverlayPlot {
  std::string title;
  std::vector<OverlayPanel> panels;
};

/// How the writing of a plot ended. A plot is an extra of a result: without
/// gnuplot, or when gnuplot fails, the result is written without it and a
/// warning says why. A plot that cannot be stored (a full disk, a quota, a
/// file-size limit) is an error like any other file that cannot be written.
struct PlotOutcome {
  enum class Kind {
    written,         // a complete PNG
    no_gnuplot,      // gnuplot is not installed
    gnuplot_failed,  // gnuplot ended with an error, the folder takes data
    write_failed,    // the PNG could not be stored
  };
  Kind kind = Kind::written;
  std::string reason;  // why not written, for a message: "gnuplot is not installed"

  bool written() const { return kind == Kind::written; }
};

/// Writes `file` (PNG) with gnuplot and says how it went (plot_outcome);
/// the caller discards the file unless it was written.
PlotOutcome write_overlay_png(const OverlayPlot& plot, const std::filesystem::path& file);

/// What gnuplot's run left in `file`; `shell_status` as pclose() returns it
/// for `sh -c gnuplot` (the shell exits with 127 when there is no gnuplot).
/// A PNG that is incomplete after gnuplot reported success was not stored:
/// gnuplot (cairo) does not check its writes. Otherwise the folder is probed
/// by writing a block of data into `file` (which is the plot's own temporary):
/// when that fails too (ENOSPC, EDQUOT, EFBIG...), the write failed, with the
/// system's reason; when it does not, gnuplot itself failed.
PlotOutcome plot_outcome(int shell_status, const std::filesystem::path& file);

}  // namespace softglass
