#include "macro/app/operating_points.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <algorithm>

#include "common/errors.h"
#include "common/progress.h"
#include "macro/app/mpi_gather.h"

namespace softglass::macro::app {

std::string describe_model(const Material& material, const fe::SolverSettings& settings) {
  return fmt::format("material: tau_y = {} Pa, K = {} Pa s^n, n = {}; solver: preset {}, {}",
                     material.shear.yield_stress, material.shear.consistency,
                     material.shear.flow_index, settings.preset,
                     settings.method == fe::Method::regularised
                         ? settings.regularisation + " regularisation"
                         : std::string("augmented Lagrangian"));
}

RankGroups::RankGroups(std::size_t points, unsigned ranks_per_point) {
  const MPI_Comm world = MPI_COMM_WORLD;
  const unsigned rank = dealii::Utilities::MPI::this_mpi_process(world);
  const unsigned ranks = dealii::Utilities::MPI::n_mpi_processes(world);
  if (ranks_per_point == 0)
    ranks_per_point = std::max<std::size_t>(1, ranks / std::max<std::size_t>(points, 1));
  ranks_per_point_ = std::min(ranks_per_point, ranks);
  groups_ = (ranks + ranks_per_point_ - 1) / ranks_per_point_;
  group_index_ = rank / ranks_per_point_;
  leader_ = rank % ranks_per_point_ == 0;
  if (ranks_per_point_ > 1) MPI_Comm_split(world, int(group_index_), int(rank), &group_);
}

RankGroups::~RankGroups() {
  if (group_ != MPI_COMM_SELF) MPI_Comm_free(&group_);
}

namespace {

// Writes the fields of the scene's last point: every rank of the group writes
// its cells into one file, under the leader's temporary name.
void write_fields(const Scene& scene, const std::filesystem::path& file, const RankGroups& groups) {
  std::unique_ptr<AtomicOutput> out;
  std::string temporary;
  if (groups.leader()) {
    out = std::make_unique<AtomicOutput>(file, true);
    temporary = out->temporary_path().string();
  }
  temporary = broadcast_text(groups.mesh_communicator(), temporary);
  scene.write_vtu(temporary);
  MPI_Barrier(groups.mesh_communicator());
  if (out) out->commit();
}

}  // namespace

std::vector<SceneResult> solve_operating_points(Scene& scene, const std::vector<double>& points,
                                                const RankGroups& groups,
                                                const SweepDisplay& display) {
  const MPI_Comm world = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(world) == 0;
  const Column drive = scene.drive();
  // Contiguous blocks, rounded up so that with fewer points than groups the
  // first groups (the whole ones; only the last may be short of ranks) work.
  const auto boundary = [&](std::size_t g) {
    return (points.size() * g + groups.groups() - 1) / groups.groups();
  };
  const std::size_t first = boundary(groups.group()), last = boundary(groups.group() + 1);
  Progress progress(display.label, double(last - first), display.quiet || !root);
  std::vector<std::vector<double>> mine;
  std::string failure;  // a rank that fails still joins the gather below
  for (std::size_t k = first; k < last && failure.empty(); ++k) {
    try {
      const SceneResult result = scene.solve(points[k]);
      if (groups.leader()) mine.push_back(result.pack());
      if (display.vtu == "all" || (display.vtu == "last" && k + 1 == points.size()))
        write_fields(scene, display.directory / fmt::format("solution_{:03d}.vtu", k), groups);
    } catch (const std::exception& error) {
      failure = fmt::format("{} = {}: {}", drive.name, points[k], error.what());
    }
    progress.update(double(k + 1 - first), fmt::format("{} = {:.4g}", drive.name, points[k]));
  }
  progress.finish();
  const auto rows = gather_rows(world, mine);
  for (const std::string& f : gather_text(world, failure))
    if (!f.empty()) throw NumericalError(f);
  std::vector<SceneResult> results;
  for (const auto& row : rows) results.push_back(SceneResult::unpack(row));
  return results;
}

ClaimedOutputs claim_outputs(const std::filesystem::path& directory,
                             const std::vector<std::string>& names, bool force) {
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  ClaimedOutputs claimed;
  std::string refusal;
  if (root) {
    std::filesystem::create_directories(directory);
    try {
      for (const std::string& name : names)
        claimed.files.push_back(std::make_unique<AtomicOutput>(directory / name, force));
    } catch (const OutputExistsError& error) {
      refusal = error.what();
      claimed.files.clear();
    }
  }
  if (broadcast_flag(comm, !refusal.empty())) {
    if (root) throw OutputExistsError(refusal);
    claimed.refused = true;
  }
  return claimed;
}

}  // namespace softglass::macro::app
