// The structure analysis as CSV tables with units in every header:
//   PREFIX_harmonics.csv   r, g_lm(r) and (fg)_lm(r) with their errors
//   PREFIX_map.csv         r, theta, g(r, theta)
//   PREFIX_summary.csv     r_m, f_m, Sigma_m, f_m Sigma_m, the elastic stresses
#pragma once

#include <string>

#include "common/atomic_output.h"
#include "micro/io/run_file.h"

namespace softglass::micro {

class StructureCsv {
 public:
  /// Claims the three files: OutputExistsError if one exists and `force` is
  /// false, before the analysis is computed.
  StructureCsv(const std::string& prefix, bool force);
  /// Writes them (atomically each).
  void write(const StructureRecord& record);

 private:
  AtomicOutput harmonics_, map_, summary_;
};

}  // namespace softglass::micro
