#include "macro/app/run.h"

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/progress.h"
#include "common/version.h"
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
  std::filesystem::create_directories(directory);
  // Both results are claimed before any work, so that a refusal costs nothing.
  AtomicOutput csv_file(directory / "results.csv", options.force);
  AtomicOutput summary_file(directory / "summary.txt", options.force);

  std::unique_ptr<Scene> scene =
      make_scene(prm, material, settings, options.scene_file.parent_path());
  const Column drive = scene->drive();
  const std::vector<Column> columns = scene->columns();

  std::ofstream csv(csv_file.temporary_path());
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

  Progress progress(fmt::format("macro {}", options.scene_file.filename().string()),
                    double(points.size()), options.quiet);
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < points.size(); ++k) {
    rows.push_back(scene->solve(points[k]));
    csv << fmt::format("{:.10g}", points[k]);
    for (double v : rows.back()) csv << fmt::format(",{:.10g}", v);
    csv << "\n";
    if (vtu == "all" || (vtu == "last" && k + 1 == points.size())) {
      const auto file = directory / fmt::format("solution_{:03d}.vtu", k);
      AtomicOutput out(file, true);
      scene->write_vtu(out.temporary_path());
      out.commit();
    }
    progress.update(double(k + 1), fmt::format("{} = {:.4g}", drive.name, points[k]));
  }
  progress.finish();
  csv.close();
  if (!csv) throw NumericalError(fmt::format("cannot write {}", csv_file.final_path().string()));

  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream summary(summary_file.temporary_path());
  summary << fmt::format("softglass macro {} ({})\n", kVersion, kGitRevision);
  summary << "scene file: " << options.scene_file.string() << "\n";
  summary << scene->description() << "\n";
  summary << fmt::format("operating points: {}; wall time {:.3f} s\n", points.size(), wall);
  // The largest relative error estimates over the sweep (primary output).
  double disc = 0.0, reg = 0.0;
  for (const auto& row : rows) {
    if (row[0] == 0.0) continue;
    disc = std::max(disc, std::abs(row[1] / row[0]));
    reg = std::max(reg, std::abs(row[2] / row[0]));
  }
  summary << fmt::format(
      "largest estimated relative {} error: discretisation {:.2e}, regularisation {:.2e}\n",
      columns[0].name, disc, reg);
  summary << "\nfull parameter set:\n";
  prm.print_parameters(summary, dealii::ParameterHandler::Text);
  summary.close();
  csv_file.commit();
  summary_file.commit();
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
