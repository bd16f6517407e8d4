// What the `bridge` subcommands print: the results in a form to read, next to
// the paper's values where there are any.
#pragma once

#include <string>
#include <vector>

#include "bridge/material/material.h"
#include "bridge/rescale/rescale.h"
#include "bridge/sweep/analysis.h"

namespace softglass::bridge {

void print_fit_report(const SweepAnalysis& analysis, const std::string& source);
void print_material_report(const Material& material);
void print_rescale_report(const std::vector<RescaledCurve>& rescaled,
                          const RescaleSettings& settings, const std::string& constants_source);

/// "80.7 ± 1.3": a value with its error, to `digits` significant digits of the error.
std::string with_error(double value, double error, int digits = 2);

}  // namespace softglass::bridge
