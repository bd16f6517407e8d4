// The /oscillation group of an oscillatory run's file (docs/output.md): the
// protocol, the sampled series with its times and rates, each cycle's
// response, the periodic summary, the Lissajous figure of the last cycle, the
// counters and the final configuration.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/h5_file.h"
#include "micro/protocol/oscillatory_run.h"

namespace softglass::micro {

/// What an oscillatory run adds to its record (run_file.h).
struct OscillationRecord {
  OscillationProtocol protocol;
  OscillationResult result;
  Particles final_particles;  // label order
  LeesEdwardsBox final_box;
  std::string integrator;  // after `auto` was resolved, e.g. "implicit, tolerance 1e-05"
};

void write_oscillation(H5Group&& g, const OscillationRecord& record);

/// What an oscillatory run concluded, read back for the tables.
struct StoredOscillationSummary {
  std::filesystem::path file;
  double volume_fraction = 0.0, amplitude = 0.0, frequency = 0.0;
  double shear_modulus = 0.0, flow_gradient_modulus = 0.0;  // the packing's static G0, x–y G0
  std::size_t particles = 0, periodic_cycles = 0;
  bool converged = false;
  std::vector<ObservableEstimate> observables;  // oscillation_observable_names() order
  std::uint64_t packing_fingerprint = 0;        // as StoredRunSummary's
};
/// InputError naming the file and entry for a file without /oscillation, or
/// with a missing, non-finite or out-of-range entry.
StoredOscillationSummary read_oscillation_summary(const std::filesystem::path& path);

}  // namespace softglass::micro
