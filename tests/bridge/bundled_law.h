// The law of the project's paper sweep (cases/bridge_law_paper_sweep.prm) with
// its simulated points, as the tests of the tabulated material and of the
// predictions read it (deal.II's reader: bridge_prm_tests only).
#pragma once

#include <filesystem>

#include "bridge/app/law_file.h"
#include "bridge/material/tabulated_material.h"

namespace softglass::bridge::testing {

inline const std::filesystem::path kBundledLaw =
    std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" / "bridge_law_paper_sweep.prm";

struct BundledLaw {
  Law law = read_law_file(kBundledLaw);
  SimulatedCurves curves = read_simulated_curves(kBundledLaw, law);
};

}  // namespace softglass::bridge::testing
