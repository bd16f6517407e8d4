#include "macro/app/run.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/progress.h"
#include "common/version.h"
#include "macro/app/mpi_gather.h"
#include "macro/app/scene_file.h"
#include "macro/material/material_parameters.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

namespace {

std::string header(const Column& c) {
  return fmt::format("{} [{}]", c.name, c.unit);
}

}  // namespace

int run(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  dealii::ParameterHandler prm;
  declare_scene_file(prm);
  parse_scene_file(prm, options.scene_file);
  if (!options.preset.empty()) {
    prm.enter_subsection("solver");
    try {
      prm.set("preset", options.preset);
    } catch (const dealii::ExceptionBase&) {
      throw InputError(
          fmt::format("--preset {} is unknown; allowed: fast, standard, accurate", options.preset));
    }
    prm.leave_subsection();
  }
  const Material material = read_material(prm);
  const fe::SolverSettings settings = fe::read_solver_settings(prm);
  const std::vector<double> points = read_sweep(prm);
  prm.enter_subsection("output");
  const std::string vtu = prm.get("vtu");
  prm.leave_subsection();

  const std::filesystem::path directory =
      options.output.empty()
          ? std::filesystem::path(options.scene_file.stem().string() + "_results")
          : options.output;

  // MPI: the operating points are split into contiguous blocks, one per rank
  // (each block warm-starts along itself); rank 0 gathers the rows and writes
  // the tables. Every rank parses and validates the input, so bad input stops
  // all of them alike; rank 0 alone claims the output and tells the others.
  const MPI_Comm comm = MPI_COMM_WORLD;
  const unsigned rank = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  std::unique_ptr<AtomicOutput> csv_file, summary_file;
  std::string refusal;
  if (rank == 0) {
    std::filesystem::create_directories(directory);
    // Both results are claimed before any work, so that a refusal costs nothing.
    try {
      csv_file = std::make_unique<AtomicOutput>(directory / "results.csv", options.force);
      summary_file = std::make_unique<AtomicOutput>(directory / "summary.txt", options.force);
    } catch (const OutputExistsError& error) {
      refusal = error.what();
    }
  }
  if (broadcast_flag(comm, !refusal.empty())) {
    if (rank == 0) throw OutputExistsError(refusal);
    return kExitOutputExists;
  }

  std::unique_ptr<Scene> scene =
      make_scene(prm, material, settings, options.scene_file.parent_path());
  const Column drive = scene->drive();
  const std::vector<Column> columns = scene->columns();

  const std::size_t first = points.size() * rank / ranks;
  const std::size_t last = points.size() * (rank + 1) / ranks;
  Progress progress(fmt::format("macro {}", options.scene_file.filename().string()),
                    double(last - first), options.quiet || rank != 0);
  std::vector<std::vector<double>> mine;
  std::string failure;  // a rank that fails still joins the gather below
  for (std::size_t k = first; k < last && failure.empty(); ++k) {
    try {
      mine.push_back(scene->solve(points[k]));
      if (vtu == "all" || (vtu == "last" && k + 1 == points.size())) {
        const auto file = directory / fmt::format("solution_{:03d}.vtu", k);
        AtomicOutput out(file, true);
        scene->write_vtu(out.temporary_path());
        out.commit();
      }
    } catch (const std::exception& error) {
      failure = fmt::format("{} = {}: {}", drive.name, points[k], error.what());
    }
    progress.update(double(k + 1 - first), fmt::format("{} = {:.4g}", drive.name, points[k]));
  }
  progress.finish();
  const auto rows = gather_rows(comm, mine, columns.size());
  const auto failures = gather_text(comm, failure);
  if (rank != 0) return kExitOk;
  for (const std::string& f : failures)
    if (!f.empty()) throw NumericalError(f);

  std::ofstream csv(csv_file->temporary_path());
  csv << "# " << scene->description() << "\n";
  csv << fmt::format("# material: tau_y = {} Pa, K = {} Pa s^n, n = {}; solver: preset {}, {}",
                     material.shear.yield_stress, material.shear.consistency,
                     material.shear.flow_index, settings.preset,
                     settings.method == fe::Method::regularised
                         ? settings.regularisation + " regularisation"
                         : std::string("augmented Lagrangian"))
      << "\n";
  csv << header(drive);
  for (const Column& c : columns) csv << "," << header(c);
  csv << "\n";
  for (std::size_t k = 0; k < points.size(); ++k) {
    csv << fmt::format("{:.10g}", points[k]);
    for (double v : rows[k]) csv << fmt::format(",{:.10g}", v);
    csv << "\n";
  }
  csv.close();
  if (!csv) throw NumericalError(fmt::format("cannot write {}", csv_file->final_path().string()));

  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream summary(summary_file->temporary_path());
  summary << fmt::format("softglass macro {} ({})\n", kVersion, kGitRevision);
  summary << "scene file: " << options.scene_file.string() << "\n";
  summary << scene->description() << "\n";
  summary << fmt::format("operating points: {} on {} MPI rank(s); wall time {:.3f} s\n",
                         points.size(), ranks, wall);
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
  summary << "\nfull parameter set:\n";
  prm.print_parameters(summary, dealii::ParameterHandler::Text);
  summary.close();
  csv_file->commit();
  summary_file->commit();
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
