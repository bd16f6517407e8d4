// The CSV tables `bridge fit` and `bridge rescale` write next to their main
// output, for plots (scripts/plot_bridge.py) and further analysis. Every column
// name carries its units; `_se` columns are one standard deviation.
//
// fit, per volume fraction (<stem>_phi.csv): G0, γ_y, and for each quantity the
// Herschel–Bulkley parameters with errors and goodness of fit, each φ's own
// universal constant and the universal fit's yield value; beside σ_y, when the
// table has quasi-static (γ̃ = 0) rows, their σ (NaN for a φ without one).
// fit, per state point (<stem>_points.csv): the table's values and standard
// errors, the smoothed errors used as weights, the Herschel–Bulkley model, and
// the collapse coordinates γ̃/γ_y² and σ/σ_y, N1/σ_y, −N2/σ_y of the universal
// laws (Fig. 4).
// fit, constants (<stem>_constants.csv): k, k′, k″ and the mean exponent with
// errors, the paper's values, and the collapse test.
// rescale, per point (<stem>.csv) and per curve (<stem>_curves.csv).
#pragma once

#include <string>
#include <vector>

#include "bridge/rescale/rescale.h"
#include "bridge/sweep/analysis.h"

namespace softglass::bridge {

std::string phi_table(const SweepAnalysis& a, const std::vector<std::string>& comments);
std::string points_table(const SweepAnalysis& a, const std::vector<std::string>& comments);
std::string constants_table(const SweepAnalysis& a, const std::vector<std::string>& comments);

std::string rescaled_points_table(const std::vector<MeasuredCurve>& curves,
                                  const std::vector<RescaledCurve>& rescaled,
                                  const std::vector<std::string>& comments);
std::string rescaled_curves_table(const std::vector<RescaledCurve>& rescaled,
                                  const RescaleSettings& settings,
                                  const std::vector<std::string>& comments);

}  // namespace softglass::bridge
