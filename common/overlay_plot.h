// A PNG of predicted against measured curves (gnuplot, from Debian's
// gnuplot-nox), for `macro compare` and `bridge amplitude-sweep`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace softglass {

/// One measured and one predicted series over a common abscissa.
struct OverlaySeries {
  std::string quantity;  // axis label, with its unit: "torque [N m]"
  std::vector<double> measured, predicted;
};

struct OverlayPlot {
  std::string title;
  std::string abscissa;  // axis label, with its unit
  std::vector<double> x;
  std::vector<OverlaySeries> panels;  // one panel each, with the relative error below
};

/// Writes `file` (PNG) with gnuplot; false when gnuplot is not installed,
/// fails, or leaves an incomplete PNG (a full disk), so that the caller can
/// say so (and discard the file).
bool write_overlay_png(const OverlayPlot& plot, const std::filesystem::path& file);

}  // namespace softglass
