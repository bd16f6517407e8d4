#include "macro/app/compare.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/csv_table.h"
#include "common/errors.h"
#include "common/version.h"
#include "macro/app/measured_torques.h"
#include "macro/app/operating_points.h"
#include "macro/app/results_file.h"
#include "macro/app/scene_file.h"
#include "macro/io/overlay_plot.h"
#include "macro/material/material_parameters.h"

namespace softglass::macro::app {

namespace {

// How far the predictions are from the measurements, e = predicted/measured − 1.
struct Agreement {
  std::size_t points = 0;
  double mean = 0.0, rms = 0.0, median_abs = 0.0, max_abs = 0.0;
  double max_at = 0.0;  // the angular velocity of the largest |e|
};

Agreement agreement(const std::vector<double>& omega, const std::vector<double>& measured,
                    const std::vector<double>& predicted) {
  Agreement a;
  std::vector<double> abs_errors;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const double e = predicted[i] / measured[i] - 1.0;
    a.mean += e;
    a.rms += e * e;
    abs_errors.push_back(std::abs(e));
    if (std::abs(e) >= a.max_abs) {
      a.max_abs = std::abs(e);
      a.max_at = omega[i];
    }
  }
  a.points = measured.size();
  a.mean /= double(a.points);
  a.rms = std::sqrt(a.rms / double(a.points));
  std::sort(abs_errors.begin(), abs_errors.end());
  const std::size_t h = a.points / 2;
  a.median_abs = a.points % 2 ? abs_errors[h] : 0.5 * (abs_errors[h - 1] + abs_errors[h]);
  return a;
}

std::string describe(const std::string& what, const Agreement& a) {
  return fmt::format(
      "{}: {} points, predicted/measured - 1: mean {:+.1f} %, rms {:.1f} %, median |.| {:.1f} %, "
      "max |.| {:.1f} % at Omega = {:.4g} rad/s",
      what, a.points, 100 * a.mean, 100 * a.rms, 100 * a.median_abs, 100 * a.max_abs, a.max_at);
}

const RheometerCurve& select_curve(const std::vector<RheometerCurve>& curves,
                                   const CompareOptions& o) {
  std::vector<std::string> labels;
  for (const auto& c : curves) labels.push_back(c.label);
  if (o.sample.empty()) {
    require(curves.size() == 1,
            fmt::format("{} holds {} curves ({}); choose one with --sample", o.data_file.string(),
                        curves.size(), fmt::join(labels, ", ")));
    return curves[0];
  }
  for (const auto& c : curves)
    if (c.label == o.sample) return c;
  throw InputError(fmt::format("--sample {}: no such curve in {}; allowed: {}", o.sample,
                               o.data_file.string(), fmt::join(labels, ", ")));
}

InstrumentConstants instrument_constants(const Scene& scene, const std::string& scene_name,
                                         const CompareOptions& o) {
  const auto standard = scene.instrument();
  require(standard.has_value(),
          fmt::format("scene = {} has no rheometer torque to compare; allowed: couette, "
                      "cone-plate, parallel-plates",
                      scene_name));
  InstrumentConstants c = *standard;
  for (auto [option, given, slot] :
       {std::tuple{"--strain-constant", o.strain_constant, &c.strain_constant},
        std::tuple{"--stress-constant", o.stress_constant, &c.stress_constant}}) {
    if (!given) continue;
    require(std::isfinite(*given) && *given > 0.0,
            fmt::format("{} = {} is not allowed; allowed: > 0", option, *given));
    *slot = *given;
    c.convention = "the instrument's constants from the command line";
  }
  return c;
}

std::size_t column_index(const std::vector<Column>& columns, const std::string& name) {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].name == name) return c;
  return columns.size();
}

}  // namespace

int compare(const CompareOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  dealii::ParameterHandler prm;
  auto [material, settings] = read_scene_input(prm, o.scene_file, o.preset, o.material);
  const std::string scene_name = prm.get("scene");
  std::unique_ptr<Scene> scene = make_scene(prm, material, settings, o.scene_file.parent_path());
  const InstrumentConstants constants = instrument_constants(*scene, scene_name, o);

  require(o.min_rate >= 0.0 && o.max_rate > o.min_rate,
          fmt::format("--min-rate {} and --max-rate {}: allowed 0 <= min < max", o.min_rate,
                      o.max_rate));
  const auto curves =
      read_rheometer_curves(CsvTable::read(o.data_file), {o.rate_unit, o.stress_unit});
  const RheometerCurve& curve = select_curve(curves, o);
  const MeasuredTorques measured = measured_torques(curve, constants, o.min_rate, o.max_rate);

  const std::filesystem::path directory =
      o.output.empty() ? std::filesystem::path(fmt::format("{}_vs_{}", o.data_file.stem().string(),
                                                           o.scene_file.stem().string()))
                       : o.output;
  ClaimedOutputs claimed = claim_outputs(
      directory, {"comparison.csv", "summary.txt", "comparison.png", "comparison.h5"}, o.force);
  if (claimed.refused) return kExitOutputExists;
  // The number of points is known now; when ranks are to share meshes, the
  // scene is made again on its group's ranks.
  const RankGroups groups(measured.angular_velocity.size(), o.ranks_per_point);
  if (groups.ranks_per_point() > 1) {
    settings.mesh_communicator = groups.mesh_communicator();
    scene = make_scene(prm, material, settings, o.scene_file.parent_path());
  }

  // The scene at the measured angular velocities (increasing: each solve
  // warm-starts from the previous one).
  const std::vector<std::vector<double>> rows = solve_operating_points(
      *scene, measured.angular_velocity, groups,
      {.directory = directory,
       .vtu = "none",
       .label = fmt::format("macro compare {}", o.data_file.filename().string()),
       .quiet = o.quiet});
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) return kExitOk;

  const std::vector<Column> columns = scene->columns();
  const std::size_t torque = column_index(columns, "torque");
  const std::size_t disc = column_index(columns, "torque_discretisation_error");
  const std::size_t reg = column_index(columns, "torque_regularisation_error");
  const std::size_t yielded = column_index(columns, "yielded_fraction");
  const std::size_t force = column_index(columns, "normal_force");
  const bool compare_force = measured.normal_force && force < columns.size();
  const std::size_t n = rows.size();
  std::vector<double> predicted(n), predicted_force(n);
  for (std::size_t i = 0; i < n; ++i) {
    predicted[i] = rows[i][torque];
    if (compare_force) predicted_force[i] = rows[i][force];
  }
  const Agreement torques = agreement(measured.angular_velocity, measured.torque, predicted);
  std::vector<std::string> report{describe("torque", torques)};
  if (compare_force) {
    report.push_back(describe("normal force", agreement(measured.angular_velocity,
                                                        *measured.normal_force, predicted_force)));
  } else if (measured.normal_force) {
    report.push_back(
        "normal force: measured but not predicted by this scene and material (no N1 law, or a "
        "Couette cell, where the axial force is not a material function): not compared");
  }

  // The table, point by point.
  std::vector<Column> table{
      {"angular_velocity", "rad/s"}, {"shear_rate", "1/s"},
      {"measured_torque", "N m"},    {"predicted_torque", "N m"},
      {"relative_error", "1"},       {"predicted_torque_error_estimate", "N m"},
      {"measured_stress", "Pa"},     {"predicted_stress", "Pa"},
      {"yielded_fraction", "1"}};
  if (compare_force) {
    table.insert(table.end(), {{"measured_normal_force", "N"},
                               {"predicted_normal_force", "N"},
                               {"normal_force_relative_error", "1"}});
  }
  std::vector<std::vector<double>> table_rows;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double>& v = table_rows.emplace_back(std::vector<double>{
        measured.angular_velocity[i], measured.shear_rate[i], measured.torque[i], predicted[i],
        predicted[i] / measured.torque[i] - 1.0, std::abs(rows[i][disc]) + std::abs(rows[i][reg]),
        measured.stress[i], constants.stress_constant * predicted[i], rows[i][yielded]});
    if (compare_force) {
      v.insert(v.end(), {(*measured.normal_force)[i], predicted_force[i],
                         predicted_force[i] / (*measured.normal_force)[i] - 1.0});
    }
  }
  std::vector<std::string> header_lines{
      fmt::format("softglass macro compare {} ({})", kVersion, kGitRevision),
      fmt::format("scene: {} ({})", o.scene_file.string(), scene->description()),
      fmt::format("data: {}, curve '{}', {} points compared, {} outside the rate window",
                  o.data_file.string(), curve.label, n, measured.left_out),
      describe_model(material, settings)};
  for (const std::string& c : measured.conversions) header_lines.push_back("derived: " + c);

  AtomicOutput& csv_file = *claimed.files[0];
  write_results_csv(csv_file, header_lines, {table, table_rows}, 8);

  io::OverlayPlot plot{
      .title = fmt::format("{}{}\npredicted: {}", o.data_file.filename().string(),
                           curve.label == o.data_file.stem().string() ? "" : ", " + curve.label,
                           o.scene_file.filename().string()),
      .abscissa = "angular velocity {/Symbol W} [rad/s]",
      .x = measured.angular_velocity,
      .panels = {{"torque [N m]", measured.torque, predicted}}};
  if (compare_force)
    plot.panels.push_back({"normal force [N]", *measured.normal_force, predicted_force});
  AtomicOutput& png_file = *claimed.files[2];
  const bool plotted = io::write_overlay_png(plot, png_file.temporary_path());
  if (plotted) png_file.commit();

  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  AtomicOutput& summary_file = *claimed.files[1];
  std::ofstream summary(summary_file.temporary_path());
  for (const std::string& line : header_lines) summary << line << "\n";
  for (const std::string& line : report) summary << line << "\n";
  summary << fmt::format("wall time {:.2f} s on {} MPI rank(s), {} per point's mesh\n", wall,
                         dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                         groups.ranks_per_point());
  if (!plotted) summary << "no plot: gnuplot is not installed or failed\n";
  summary.close();
  if (!summary)
    throw NumericalError(fmt::format("cannot write {}", summary_file.final_path().string()));
  std::ostringstream parameters;
  prm.print_parameters(parameters, dealii::ParameterHandler::Text);
  AtomicOutput& h5_file = *claimed.files[3];
  write_results_h5(h5_file.temporary_path(), {table, table_rows},
                   {.software = header_lines[0],
                    .scene_file = o.scene_file.string(),
                    .description = fmt::format(
                        "{}\n", fmt::join(header_lines.begin() + 1, header_lines.end(), "\n")),
                    .model = describe_model(material, settings),
                    .parameters = parameters.str(),
                    .wall_time = wall,
                    .mpi_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                    .ranks_per_point = groups.ranks_per_point()});
  csv_file.commit();
  summary_file.commit();
  h5_file.commit();

  if (!o.quiet) {
    std::cout << fmt::format("{:>14} {:>12} {:>14} {:>14} {:>8}\n", "Omega [rad/s]", "rate [1/s]",
                             "measured [N m]", "predicted", "error");
    for (std::size_t i = 0; i < n; ++i) {
      std::cout << fmt::format("{:>14.4e} {:>12.4g} {:>14.4e} {:>14.4e} {:>+7.1f}%\n",
                               measured.angular_velocity[i], measured.shear_rate[i],
                               measured.torque[i], predicted[i],
                               100.0 * (predicted[i] / measured.torque[i] - 1.0));
    }
    for (const std::string& line : report) std::cout << line << "\n";
    std::cout << fmt::format("results: {}{}\n", (directory / "comparison.csv").string(),
                             plotted ? ", " + (directory / "comparison.png").string()
                                     : " (no plot: gnuplot is not installed)");
  }
  if (!plotted)
    std::cerr << "macro: warning: no plot written (gnuplot is not installed or failed)\n";
  return kExitOk;
}

}  // namespace softglass::macro::app
