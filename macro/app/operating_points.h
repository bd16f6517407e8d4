// Solving a scene over a list of operating points, shared by `macro run` and
// `macro compare`: the points are split into contiguous blocks over the MPI
// ranks (each block warm-starts along itself) and the rows gathered on rank 0.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/atomic_output.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

/// One line: the material law and the solver ("material: tau_y = ... ; solver: ...").
std::string describe_model(const Material& material, const fe::SolverSettings& settings);

/// What to write besides the rows, and how to show progress.
struct SweepDisplay {
  std::filesystem::path directory;  // for the VTU files
  std::string vtu = "none";         // none | last | all
  std::string label;                // of the progress bar
  bool quiet = false;
};

/// Every point's row on rank 0 (empty on the other ranks). A point that fails
/// on any rank → NumericalError on rank 0 naming the point.
std::vector<std::vector<double>> solve_operating_points(Scene& scene,
                                                        const std::vector<double>& points,
                                                        const SweepDisplay& display);

/// Rank 0 claims the result files in `directory` (created if needed) before
/// any work, so that a refusal costs nothing: OutputExistsError on rank 0, and
/// an empty list on the other ranks, which should then stop with
/// kExitOutputExists. Without a refusal, rank 0 gets one AtomicOutput per name.
struct ClaimedOutputs {
  std::vector<std::unique_ptr<AtomicOutput>> files;
  bool refused = false;  // on ranks other than 0
};
ClaimedOutputs claim_outputs(const std::filesystem::path& directory,
                             const std::vector<std::string>& names, bool force);

}  // namespace softglass::macro::app
