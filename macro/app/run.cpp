#include "macro/app/run.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <sstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/version.h"
#include "macro/app/input_scales.h"
#include "macro/app/operating_points.h"
#include "macro/app/result_folder.h"
#include "macro/app/results_file.h"
#include "macro/app/scene_file.h"
#include "macro/material/material_parameters.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

namespace {

// The largest relative error estimates of the main quantity over the sweep.
// Points where nothing yields (below the yield point) are left out: there the
// regularised material only creeps at rates ~ε and the exact output is zero,
// so a relative error means nothing; they are counted instead.
struct ErrorEstimates {
  double discretisation = 0.0, regularisation = 0.0;
  double worst_point = 0.0;  ///< the drive where the larger of the two peaks
  std::size_t unyielded = 0;
  double largest() const { return std::max(discretisation, regularisation); }
};

ErrorEstimates largest_errors(const std::vector<double>& points,
                              const std::vector<SceneResult>& results) {
  ErrorEstimates e;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const SceneResult& r = results[k];
    if (r.yielded_fraction == 0.0) {
      ++e.unyielded;
      continue;
    }
    if (r.main.value == 0.0) continue;
    const double before = e.largest();
    e.discretisation = std::max(e.discretisation, std::abs(r.main.discretisation_error / r.main.value));
    e.regularisation = std::max(e.regularisation, std::abs(r.main.regularisation_error / r.main.value));
    if (e.largest() > before) e.worst_point = points[k];
  }
  return e;
}

std::string error_summary(const std::string& quantity, const ErrorEstimates& e) {
  std::string text = fmt::format(
      "largest estimated relative {} error: discretisation {:.2e}, regularisation {:.2e}\n",
      quantity, e.discretisation, e.regularisation);
  if (e.unyielded > 0) {
    text += fmt::format(
        "{} operating point(s) below the yield point: nothing yields, the output is creep "
        "of order eps (zero for the exact law)\n",
        e.unyielded);
  }
  return text;
}

// A result whose own error estimate is this large is not a prediction: the
// mesh or ε does not resolve the flow (a yielded layer thinner than a cell, a
// thin gap's plug). The run still writes it, with the estimate beside it, and
// says so on stderr even when quiet. (The fast preset aims at about 1e-2.)
constexpr double kUnresolvedRelativeError = 0.1;

void warn_if_unresolved(const std::string& quantity, const Column& drive,
                        const ErrorEstimates& e) {
  if (e.largest() <= kUnresolvedRelativeError) return;
  std::cerr << fmt::format(
      "macro: warning: the estimated relative {} error reaches {:.3g} ({} error) at {} = {:g} "
      "[{}]: the solve does not resolve this flow; use a finer preset, more cells or more "
      "adaptive cycles (subsection solver)\n",
      quantity, e.largest(),
      e.discretisation >= e.regularisation ? "discretisation" : "regularisation", drive.name,
      e.worst_point, drive.unit);
}

// summary.txt: the scene, the sweep's cost, the largest error estimates and
// the full parameter set.
void write_summary(const std::string& file, const std::filesystem::path& scene_file,
                   const Scene& scene, const ErrorEstimates& errors, const std::string& sweep,
                   const std::string& extrapolation, const std::string& parameters) {
  write_file(file, "summary.txt", [&](std::ostream& summary) {
    summary << fmt::format("softglass macro {} ({})\n", kVersion, kGitRevision);
    summary << "scene file: " << scene_file.string() << "\n";
    summary << scene.description() << "\n";
    summary << sweep;
    summary << error_summary(scene.columns()[0].name, errors);
    if (!extrapolation.empty()) summary << extrapolation << "\n";
    summary << "\nfull parameter set:\n" << parameters;
  });
}

// The field files of `output = vtu`: none, the last point's, or every point's.
std::map<std::size_t, std::string> field_names(const std::string& vtu, std::size_t points) {
  std::map<std::size_t, std::string> names;
  for (std::size_t k = 0; k < points; ++k)
    if (vtu == "all" || (vtu == "last" && k + 1 == points))
      names[k] = fmt::format("solution_{:03d}.vtu", k);
  return names;
}

}  // namespace

int run(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  dealii::ParameterHandler prm;
  auto [material, settings, entries] =
      read_scene_input(prm, options.scene_file, options.preset, options.material);
  const std::vector<double> points = read_sweep(prm);
  const RankGroups groups(points.size(), options.ranks_per_point);
  settings.mesh_communicator = groups.mesh_communicator();
  prm.enter_subsection("output");
  const std::string vtu = prm.get("vtu");
  prm.leave_subsection();

  const std::filesystem::path directory =
      options.output.empty()
          ? std::filesystem::path(options.scene_file.stem().string() + "_results")
          : options.output;
  // Every rank parses and validates the input (building the scene checks its
  // entries), so bad input stops all of them alike and leaves no folder
  // behind; rank 0 then claims the output and writes the tables, every rank
  // the field files of its points (result_folder.h).
  check_entry_scales(entries, options.scene_file);
  std::unique_ptr<Scene> scene =
      make_scene(prm, material, settings, options.scene_file.parent_path());
  check_derived_scales(*scene, material, settings, points, entries, options.scene_file);
  const std::map<std::size_t, std::string> fields = field_names(vtu, points.size());
  std::vector<std::string> names{"results.csv", "summary.txt", "results.h5"};
  for (const auto& [point, name] : fields) names.push_back(name);
  ResultFolder folder(directory, names, options.force);
  if (folder.refused()) return kExitOutputExists;
  SweepDisplay display{.settings = settings,
                       .label = fmt::format("macro {}", options.scene_file.filename().string()),
                       .quiet = options.quiet};
  for (const auto& [point, name] : fields) display.field_files[point] = folder.temporary(name);
  const auto results = solve_operating_points(*scene, points, groups, display);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) return kExitOk;
  const unsigned ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  const UnitTable table = results_table(*scene, points, results);
  write_results_csv(folder.temporary("results.csv"), folder.path("results.csv"),
                    {scene->description(), describe_model(material, settings)}, table, 10);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream parameters;
  prm.print_parameters(parameters, dealii::ParameterHandler::Text);
  const ErrorEstimates errors = largest_errors(points, results);
  const std::string extrapolation = extrapolation_note(*scene, material, points);
  write_summary(folder.temporary("summary.txt"), options.scene_file, *scene, errors,
                fmt::format("operating points: {} on {} MPI rank(s), {} per point's mesh; wall "
                            "time {:.3f} s\n",
                            points.size(), ranks, groups.ranks_per_point(), wall),
                extrapolation, parameters.str());
  write_results_h5(folder.temporary("results.h5"), table,
                   {.software = fmt::format("softglass macro {} ({})", kVersion, kGitRevision),
                    .scene_file = options.scene_file.string(),
                    .description = scene->description(),
                    .model = describe_model(material, settings),
                    .parameters = parameters.str(),
                    .wall_time = wall,
                    .mpi_ranks = ranks,
                    .ranks_per_point = groups.ranks_per_point()});
  folder.commit();
  warn_if_unresolved(scene->columns()[0].name, scene->drive(), errors);
  if (!extrapolation.empty()) std::cerr << "macro: " << extrapolation << "\n";
  if (!options.quiet) {
    std::cout << fmt::format("{} operating points in {:.2f} s; results in {}\n", points.size(),
                             wall, directory.string());
  }
  return kExitOk;
}

void print_template() {
  dealii::ParameterHandler prm;
  declare_scene_file(prm);
  prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
}

}  // namespace softglass::macro::app
