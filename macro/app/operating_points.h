// Solving a scene over a list of operating points, shared by `macro run` and
// `macro compare`. The MPI ranks form groups of consecutive ranks; the points
// are split into contiguous blocks, one per group (each block warm-starts
// along itself); the ranks of a group share each point's mesh (a distributed
// triangulation, scalar_flow_solver.cpp), and the rows are gathered on rank 0.
#pragma once

#include <mpi.h>

#include <map>
#include <string>
#include <vector>

#include "macro/scenes/scene.h"

namespace softglass::macro::app {

/// One line: the material law and the solver ("material: tau_y = ... ; solver: ...").
std::string describe_model(const Material& material, const fe::SolverSettings& settings);

/// Empty, or one line saying at how many operating points the scene's
/// characteristic shear rate lies outside the window of a tabulated law,
/// where the law is its power-law extrapolation (tabulated_law.h).
std::string extrapolation_note(const Scene& scene, const Material& material,
                               const std::vector<double>& points);

/// The table of results.csv and results.h5 (and of the Python module's
/// run_scene): the operating point, then the scene's columns, a row per point.
UnitTable results_table(const Scene& scene, const std::vector<double>& points,
                        const std::vector<SceneResult>& results);

/// What to write besides the rows, and how to show progress.
struct SweepDisplay {
  /// The points whose fields are written (VTU), and where: the temporary name
  /// of the file (result_folder.h), the same on every rank.
  std::map<std::size_t, std::string> field_files{};
  /// The scene's solver settings (for the cost model).
  fe::SolverSettings settings{};
  std::string label;  // of the progress bar
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

/// The cost model (docs/macro.md, "Cost of a sweep"): the unknowns of one
/// point's final mesh, from the coarse mesh, the preset's uniform refinements
/// and adaptive cycles, times the meshes solved on.
double estimated_work(const MeshExtent& mesh, const fe::SolverSettings& settings);
/// Seconds per unit of that work: the slowest of the scalar scenes measured
/// (docs/macro.md), so that the estimate errs long.
inline constexpr double kSecondsPerWork = 4e-5;
/// The plan is stated before a sweep estimated to take longer than this [s].
inline constexpr double kPlanThreshold = 120.0;

/// Every point's result on rank 0 (empty on the other ranks). A point that
/// fails on any rank → NumericalError on rank 0 naming the point. The scene
/// must have been made with groups.mesh_communicator(). A sweep estimated
/// longer than kPlanThreshold is announced on stderr before it starts.
std::vector<SceneResult> solve_operating_points(Scene& scene, const std::vector<double>& points,
                                                const RankGroups& groups,
                                                const SweepDisplay& display);

}  // namespace softglass::macro::app
