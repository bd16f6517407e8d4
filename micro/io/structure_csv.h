// The structure analysis as CSV tables with units in every header:
//   PREFIX_harmonics.csv   r, g_lm(r) and (fg)_lm(r) with their errors
//   PREFIX_map.csv         r, theta, g(r, theta)
//   PREFIX_summary.csv     r_m, f_m, Sigma_m, f_m Sigma_m, the elastic stresses
#pragma once

#include <string>

#include "micro/io/run_file.h"

namespace softglass::micro {

/// Writes the three files (atomically each); OutputExistsError if one exists
/// and `force` is false, before anything is written.
void write_structure_csv(const std::string& prefix, const StructureRecord& record, bool force);

}  // namespace softglass::micro
