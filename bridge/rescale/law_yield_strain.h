// The yield strains of measured curves taken from a law file: each curve's
// volume fraction φ (given, or read from its label, as in digitised figures
// whose columns are labelled by φ) looked up in the law's γ_y(φ), interpolated
// between simulated volume fractions as `bridge material` does
// (material/interpolation.h). This places measured curves with the simulated
// yield strains, leaving E* (shared by the curves of one material) to fit — the
// paper's Fig. 5.
#pragma once

#include <string>
#include <vector>

#include "bridge/law/law.h"

namespace softglass::bridge {

/// γ_y at each φ. InputError when a φ is outside (0, 1), or outside the
/// simulated range without `extrapolate`.
std::vector<double> law_yield_strains(const Law& law, const std::vector<double>& phi,
                                      bool extrapolate, const std::string& source);

/// The φ of each curve read from its label ("0.68"); InputError naming a label
/// that is not a number.
std::vector<double> phi_from_labels(const std::vector<std::string>& labels);

}  // namespace softglass::bridge
