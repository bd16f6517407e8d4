#include "macro/app/operating_points.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "common/errors.h"
#include "common/progress.h"
#include "macro/app/mpi_gather.h"

namespace softglass::macro::app {

std::string describe_model(const Material& material, const fe::SolverSettings& settings) {
  const std::string source = material.source.empty() ? "" : " [" + material.source + "]";
  return fmt::format("material{}: {}; solver: preset {}, {}", source,
                     material.shear->description(), settings.preset,
                     settings.method == fe::Method::regularised
                         ? settings.regularisation + " regularisation"
                         : std::string("augmented Lagrangian"));
}

std::string extrapolation_note(const Scene& scene, const Material& material,
                               const std::vector<double>& points) {
  const auto window = material.shear->rate_window();
  if (!window) return {};
  std::size_t below = 0, above = 0;
  for (const double point : points) {
    const double rate = scene.characteristic_rate(point);
    below += rate < window->first;
    above += rate > window->second;
  }
  if (below + above == 0) return {};
  return fmt::format(
      "note: at {} of {} operating points the characteristic shear rate lies outside the "
      "tabulated law's window {:.4g} ... {:.4g} 1/s ({} below, {} above): there the law is its "
      "power-law extrapolation, not data",
      below + above, points.size(), window->first, window->second, below, above);
}

UnitTable results_table(const Scene& scene, const std::vector<double>& points,
                        const std::vector<SceneResult>& results) {
  UnitTable table{.columns = {scene.drive()}, .rows = {}};
  const std::vector<Column> columns = scene.columns();
  table.columns.insert(table.columns.end(), columns.begin(), columns.end());
  for (std::size_t k = 0; k < points.size(); ++k) {
    table.rows.push_back({points[k]});
    const std::vector<double> values = results[k].values();
    table.rows.back().insert(table.rows.back().end(), values.begin(), values.end());
  }
  return table;
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

double estimated_work(const MeshExtent& mesh, const fe::SolverSettings& settings) {
  // Each uniform refinement multiplies the cells by 2^dim; each adaptive cycle
  // splits the refined fraction into 2^dim; a Q_p cell holds ~p^dim unknowns.
  const double children = std::pow(2.0, mesh.dimension);
  const double cells = double(mesh.cells) * std::pow(children, settings.global_refinements) *
                       std::pow(1.0 + settings.refine_fraction * (children - 1.0),
                                settings.adaptive_cycles);
  const double unknowns = cells * std::pow(double(settings.fe_degree), mesh.dimension);
  return unknowns * (1.0 + settings.adaptive_cycles) * mesh.relative_cost;
}

namespace {

// One line on stderr before a long sweep: how many solves, and how long.
void announce_plan(const Scene& scene, const fe::SolverSettings& settings, std::size_t points,
                   const RankGroups& groups) {
  const std::size_t per_group = (points + groups.groups() - 1) / groups.groups();
  const double seconds = kSecondsPerWork * estimated_work(scene.mesh_extent(), settings) *
                         double(per_group);
  if (seconds <= kPlanThreshold) return;
  std::cerr << fmt::format(
      "macro: plan: {} operating points ({} per group of ranks, {} group(s)), preset {}: about "
      "{:.0f} s ({:.1f} h) by the cost model of docs/macro.md\n",
      points, per_group, groups.groups(), settings.preset, seconds, seconds / 3600.0);
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
  if (root) announce_plan(scene, display.settings, points.size(), groups);
  Progress progress(display.label, double(last - first), display.quiet || !root);
  std::vector<std::vector<double>> mine;
  std::string failure;  // a rank that fails still joins the gather below
  for (std::size_t k = first; k < last && failure.empty(); ++k) {
    try {
      const SceneResult result = scene.solve(points[k]);
      if (groups.leader()) mine.push_back(result.pack());
      // Every rank of the group writes its cells into the one file.
      if (const auto file = display.field_files.find(k); file != display.field_files.end())
        scene.write_vtu(file->second);
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

}  // namespace softglass::macro::app
