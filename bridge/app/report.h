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

/// "80.7 ± 1.3": a value with its error, to `digits` significant digits of the error.
std::string with_error(double value, double error, int digits = 2);

}  // namespace softglass::bridge
