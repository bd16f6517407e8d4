// Solving a scene over a list of operating points, shared by `macro run` and
// `macro compare`. The MPI ranks form groups of consecutive ranks; the points
// are split into contiguous blocks, one per group (each block warm-starts
// along itself); the ranks of a group share each point's mesh (a distributed
// triangulation, scalar_flow_solver.cpp), and the rows are gathered on rank 0.
#pragma once

#include <mpi.h>

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

/// The ranks of MPI_COMM_WORLD in groups of `ranks_per_point` consecutive
/// ranks (the last group may be smaller). ranks_per_point = 0 chooses: points
/// first — one rank per point while there are at least as many points as
/// ranks, the ranks shared out over the points otherwise.
class RankGroups {
 public:
  RankGroups(std::size_t points, unsigned ranks_per_point);
  ~RankGroups();
  RankGroups(const RankGroups&) = delete;
  RankGroups& operator=(const RankGroups&) = delete;

  /// This rank's group: the communicator its scenes' meshes are distributed over.
  MPI_Comm mesh_communicator() const { return group_; }
  unsigned group() const { return group_index_; }
  unsigned groups() const { return groups_; }
  unsigned ranks_per_point() const { return ranks_per_point_; }
  /// The group's first rank, which reports the group's rows.
  bool leader() const { return leader_; }

 private:
  MPI_Comm group_ = MPI_COMM_SELF;
  unsigned group_index_ = 0, groups_ = 1, ranks_per_point_ = 1;
  bool leader_ = true;
};

/// Every point's result on rank 0 (empty on the other ranks). A point that
/// fails on any rank → NumericalError on rank 0 naming the point. The scene
/// must have been made with groups.mesh_communicator().
std::vector<SceneResult> solve_operating_points(Scene& scene, const std::vector<double>& points,
                                                const RankGroups& groups,
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
