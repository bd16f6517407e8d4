// What the `bridge` subcommands print: the results in a form to read, next to
// the paper's values where there are any.
#pragma once

#include <string>
#include <vector>

#include "bridge/material/amplitude_sweep_prediction.h"
#include "bridge/material/material.h"
#include "bridge/rescale/rescale.h"
#include "bridge/sweep/analysis.h"

namespace softglass::bridge {

void print_fit_report(const SweepAnalysis& analysis, const std::string& source);
void print_material_report(const Material& material);
/// The amplitude-sweep law of `law` per volume fraction, beside the static
/// G0 and the flow curve's yield strain where the law has them.
void print_amplitude_sweep_report(const Law& law);
/// A material's amplitude sweep in SI units.
void print_amplitude_sweep_prediction(const AmplitudeSweepPrediction& p);
void print_rescale_report(const std::vector<RescaledCurve>& rescaled,
                          const RescaleSettings& settings, const std::string& constants_source);

/// "80.7 ± 1.3": a value with its error, to `digits` significant digits of the
/// error and the value to the same decimal place; `unit`, if given, follows
/// ("80.7 ± 1.3 Pa"). An error larger than the value is said in words:
/// "-0.86 Pa, not distinguishable from zero (error 3.5e+05 Pa)".
std::string with_error(double value, double error, int digits = 2, const std::string& unit = "");

}  // namespace softglass::bridge
