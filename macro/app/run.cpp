#include "macro/app/run.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/version.h"
#include "macro/app/operating_points.h"
#include "macro/app/results_file.h"
#include "macro/app/scene_file.h"
#include "macro/material/material_parameters.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

int run(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  dealii::ParameterHandler prm;
  auto [material, settings] =
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
  // behind; rank 0 alone then claims the output and writes the tables.
  std::unique_ptr<Scene> scene =
      make_scene(prm, material, settings, options.scene_file.parent_path());
  ClaimedOutputs claimed =
      claim_outputs(directory, {"results.csv", "summary.txt", "results.h5"}, options.force);
  if (claimed.refused) return kExitOutputExists;
  const Column drive = scene->drive();
  const std::vector<Column> columns = scene->columns();
  const auto rows = solve_operating_points(
      *scene, points, groups,
      {.directory = directory,
       .vtu = vtu,
       .label = fmt::format("macro {}", options.scene_file.filename().string()),
       .quiet = options.quiet});
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) return kExitOk;
  AtomicOutput& csv_file = *claimed.files[0];
  AtomicOutput& summary_file = *claimed.files[1];
  AtomicOutput& h5_file = *claimed.files[2];
  const unsigned ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  // The table of results.csv and results.h5: the operating point, then the row.
  UnitTable table{.columns = {drive}, .rows = {}};
  table.columns.insert(table.columns.end(), columns.begin(), columns.end());
  for (std::size_t k = 0; k < points.size(); ++k) {
    table.rows.push_back({points[k]});
    table.rows.back().insert(table.rows.back().end(), rows[k].begin(), rows[k].end());
  }

  write_results_csv(csv_file, {scene->description(), describe_model(material, settings)}, table,
                    10);

  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream summary(summary_file.temporary_path());
  summary << fmt::format("softglass macro {} ({})\n", kVersion, kGitRevision);
  summary << "scene file: " << options.scene_file.string() << "\n";
  summary << scene->description() << "\n";
  summary << fmt::format(
      "operating points: {} on {} MPI rank(s), {} per point's mesh; wall time {:.3f} s\n",
      points.size(), ranks, groups.ranks_per_point(), wall);
  // The largest relative error estimates over the sweep (primary output).
  // Points where nothing yields (below the yield point) are left out: there
  // the regularised material only creeps at rates ~ε and the exact output is
  // zero, so a relative error means nothing; they are counted instead.
  std::size_t yielded_column = columns.size(), unyielded = 0;
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == "yielded_fraction") yielded_column = c;
  double disc = 0.0, reg = 0.0;
  for (const auto& row : rows) {
    if (yielded_column < row.size() && row[yielded_column] == 0.0) {
      ++unyielded;
      continue;
    }
    if (row[0] == 0.0) continue;
    disc = std::max(disc, std::abs(row[1] / row[0]));
    reg = std::max(reg, std::abs(row[2] / row[0]));
  }
  summary << fmt::format(
      "largest estimated relative {} error: discretisation {:.2e}, regularisation {:.2e}\n",
      columns[0].name, disc, reg);
  if (unyielded > 0) {
    summary << fmt::format(
        "{} operating point(s) below the yield point: nothing yields, the output is creep "
        "of order eps (zero for the exact law)\n",
        unyielded);
  }
  std::ostringstream parameters;
  prm.print_parameters(parameters, dealii::ParameterHandler::Text);
  summary << "\nfull parameter set:\n" << parameters.str();
  summary.close();
  write_results_h5(h5_file.temporary_path(), table,
                   {.software = fmt::format("softglass macro {} ({})", kVersion, kGitRevision),
                    .scene_file = options.scene_file.string(),
                    .description = scene->description(),
                    .model = describe_model(material, settings),
                    .parameters = parameters.str(),
                    .wall_time = wall,
                    .mpi_ranks = ranks,
                    .ranks_per_point = groups.ranks_per_point()});
  csv_file.commit();
  summary_file.commit();
  h5_file.commit();
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
