#include "macro/app/compare.h"

#include <deal.II/base/mpi.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/csv_table.h"
#include "common/errors.h"
#include "common/overlay_plot.h"
#include "common/version.h"
#include "macro/app/input_scales.h"
#include "macro/app/measured_torques.h"
#include "macro/app/operating_points.h"
#include "macro/app/result_folder.h"
#include "macro/app/results_file.h"
#include "macro/app/scene_file.h"
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

// The constants that turn the file's shear rates and stresses into angular
// velocities and torques: the command line's, else those the export records
// (TRIOS writes its geometry's, end-effect correction included), else the
// scene geometry's standard ones. The strain constant is the geometry's alone
// (γ̇/Ω: the gap, the cone angle, the radius ratio); one recorded more than
// 1 % from the scene's means the curve was measured with another geometry
// than the scene models, which goes into `report`: the comparison would be
// between two instruments.
InstrumentConstants instrument_constants(const Scene& scene, const std::string& scene_name,
                                         const CompareOptions& o, const MeasuredFile& data,
                                         std::vector<std::string>& report) {
  const auto standard = scene.instrument();
  require(standard.has_value(),
          fmt::format("scene = {} has no rheometer torque to compare; allowed: couette, "
                      "cone-plate, parallel-plates",
                      scene_name));
  InstrumentConstants c = *standard;
  const InstrumentRecord& recorded = data.instrument;
  if (recorded.strain_constant &&
      std::abs(*recorded.strain_constant / standard->strain_constant - 1.0) > 0.01) {
    report.push_back(fmt::format(
        "warning: {} records the strain constant {:.6g} 1/rad (geometry '{}'), {:+.1f} % from "
        "the scene's {:.6g} 1/rad: the curve was measured with another geometry than the scene "
        "models",
        data.source, *recorded.strain_constant, recorded.geometry,
        100 * (*recorded.strain_constant / standard->strain_constant - 1.0),
        standard->strain_constant));
  }
  for (auto [option, given, in_file, slot] :
       {std::tuple{"--strain-constant", o.strain_constant, recorded.strain_constant,
                   &c.strain_constant},
        std::tuple{"--stress-constant", o.stress_constant, recorded.stress_constant,
                   &c.stress_constant}}) {
    if (given) {
      require(std::isfinite(*given) && *given > 0.0,
              fmt::format("{} = {} is not allowed; allowed: > 0", option, *given));
      *slot = *given;
      c.convention = "the instrument's constants from the command line";
    } else if (in_file) {
      *slot = *in_file;
      c.convention = fmt::format("the constants {} records", data.source);
    }
  }
  return c;
}

// The measured points of the chosen curve within the rate window, as torques,
// thinned to --max-points; refused when they are too many to be a flow curve.
MeasuredTorques read_measured(const CompareOptions& o, const MeasuredFile& data,
                              const InstrumentConstants& constants) {
  require(o.min_rate >= 0.0 && o.max_rate > o.min_rate,
          fmt::format("--min-rate {} and --max-rate {}: allowed 0 <= min < max", o.min_rate,
                      o.max_rate));
  require(o.max_points == 0 || o.max_points >= 2,
          fmt::format("--max-points {} is not allowed; allowed: >= 2", o.max_points));
  const auto curves =
      curves_of_kind(data, o.reading, CurveKind::flow_curve,
                     "macro compare solves a scene at a flow curve's angular velocities (an "
                     "amplitude sweep is compared by `bridge amplitude-sweep LAW --data FILE`)");
  MeasuredTorques m = measured_torques(select_curve(curves, o), constants, o.min_rate, o.max_rate);
  if (o.max_points > 0) return thinned(m, o.max_points);
  require(
      m.angular_velocity.size() <= kMostComparedPoints,
      fmt::format("{}: curve '{}' has {} points in the rate window, one solve each; a measured "
                  "flow curve has tens to hundreds, so this is taken for another kind of "
                  "file; allowed: at most {} points: narrow the window with --min-rate and "
                  "--max-rate, or compare N of them with --max-points N",
                  o.data_file.string(), m.label, m.angular_velocity.size(), kMostComparedPoints));
  return m;
}

// The measured angular velocities as entries of subsection "measurement", so
// that a scale they make unrepresentable names them (input_scales.h).
std::vector<SetEntry> measured_entries(const MeasuredTorques& m,
                                       const std::filesystem::path& data_file) {
  std::vector<SetEntry> entries;
  for (const double omega : m.angular_velocity) {
    entries.push_back({.subsections = {"measurement"},
                       .name = "angular velocity",
                       .value = fmt::format("{}", omega),
                       .file = data_file.string()});
  }
  return entries;
}

// The predictions at the measured points, side by side with the measurements.
struct Comparison {
  const MeasuredTorques& measured;
  std::vector<double> torque{}, normal_force{};  // predicted; normal force if compared
  std::vector<SceneResult> results{};
  bool compares_force = false;
};

Comparison compare_points(const MeasuredTorques& measured, std::vector<SceneResult> results) {
  Comparison c{.measured = measured, .results = std::move(results)};
  c.compares_force =
      measured.normal_force && !c.results.empty() && c.results.front().normal_force.has_value();
  for (const SceneResult& r : c.results) {
    c.torque.push_back(r.torque().value);
    if (c.compares_force) c.normal_force.push_back(*r.normal_force);
  }
  return c;
}

// One line per compared quantity (and why the normal force is not compared).
std::vector<std::string> agreement_report(const Comparison& c) {
  const MeasuredTorques& m = c.measured;
  std::vector<std::string> report{
      describe("torque", agreement(m.angular_velocity, m.torque, c.torque))};
  if (c.compares_force) {
    report.push_back(
        describe("normal force", agreement(m.angular_velocity, *m.normal_force, c.normal_force)));
  } else if (m.normal_force) {
    report.push_back(
        "normal force: measured but not predicted by this scene and material (no N1 law, or a "
        "Couette cell, where the axial force is not a material function): not compared");
  }
  return report;
}

// The table of comparison.csv and comparison.h5, point by point.
UnitTable comparison_table(const Comparison& c) {
  const MeasuredTorques& m = c.measured;
  UnitTable table{.columns = {{"angular_velocity", "rad/s"},
                              {"shear_rate", "1/s"},
                              {"measured_torque", "N m"},
                              {"predicted_torque", "N m"},
                              {"relative_error", "1"},
                              {"predicted_torque_error_estimate", "N m"},
                              {"measured_stress", "Pa"},
                              {"predicted_stress", "Pa"},
                              {"yielded_fraction", "1"}},
                  .rows = {}};
  if (c.compares_force) {
    table.columns.insert(table.columns.end(), {{"measured_normal_force", "N"},
                                               {"predicted_normal_force", "N"},
                                               {"normal_force_relative_error", "1"}});
  }
  for (std::size_t i = 0; i < c.results.size(); ++i) {
    const Estimate& torque = c.results[i].torque();
    std::vector<double>& v = table.rows.emplace_back(std::vector<double>{
        m.angular_velocity[i], m.shear_rate[i], m.torque[i], torque.value,
        torque.value / m.torque[i] - 1.0,
        std::abs(torque.discretisation_error) + std::abs(torque.regularisation_error), m.stress[i],
        m.stress_per_torque * torque.value, c.results[i].yielded_fraction});
    if (c.compares_force) {
      v.insert(v.end(), {(*m.normal_force)[i], c.normal_force[i],
                         c.normal_force[i] / (*m.normal_force)[i] - 1.0});
    }
  }
  return table;
}

// Predicted against measured: the shear stress over the shear rate (a
// rheologist's axes, both stresses with the file's stress per torque), the
// torque (and normal force) over Ω (the instrument's), into `file`.
PlotOutcome write_plot(const Comparison& c, const CompareOptions& o, const std::string& label,
                       const std::filesystem::path& file) {
  const MeasuredTorques& m = c.measured;
  const std::string omega = "angular velocity {/Symbol W} [rad/s]";
  std::vector<double> predicted_stress;
  for (const double torque : c.torque) predicted_stress.push_back(m.stress_per_torque * torque);
  OverlayPlot plot{.title = fmt::format("{}{}\npredicted: {}", o.data_file.filename().string(),
                                        label == o.data_file.stem().string() ? "" : ", " + label,
                                        o.scene_file.filename().string()),
                   .panels = {compared_panel("shear stress [Pa]", "shear rate [1/s]",
                                             m.shear_rate, m.stress, predicted_stress),
                              compared_panel("torque [N m]", omega, m.angular_velocity, m.torque,
                                             c.torque)}};
  if (c.compares_force) {
    plot.panels.push_back(compared_panel("normal force [N]", omega, m.angular_velocity,
                                         *m.normal_force, c.normal_force));
  }
  return write_overlay_png(plot, file);
}

void write_summary(const std::filesystem::path& file, const std::vector<std::string>& header_lines,
                   const std::vector<std::string>& report, double wall, unsigned ranks_per_point,
                   const PlotOutcome& plot) {
  write_file(file, "summary.txt", [&](std::ostream& summary) {
    for (const std::string& line : header_lines) summary << line << "\n";
    for (const std::string& line : report) summary << line << "\n";
    summary << fmt::format("wall time {:.2f} s on {} MPI rank(s), {} per point's mesh\n", wall,
                           dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                           ranks_per_point);
    if (!plot.written()) summary << "no plot: " << plot.reason << "\n";
  });
}

std::filesystem::path default_directory(const std::filesystem::path& data_file,
                                        const std::filesystem::path& scene_file) {
  return fmt::format("{}_vs_{}", data_file.stem().string(), scene_file.stem().string());
}

// The comment lines of comparison.csv, the head of summary.txt: what was
// compared with what, and every quantity derived rather than measured.
std::vector<std::string> provenance(const CompareOptions& o, const std::string& scene,
                                    const MeasuredTorques& measured, const std::string& model) {
  std::vector<std::string> lines{
      fmt::format("softglass macro compare {} ({})", kVersion, kGitRevision),
      fmt::format("scene: {} ({})", o.scene_file.string(), scene),
      fmt::format("data: {}, curve '{}', {} points compared, {} outside the rate window{}",
                  o.data_file.string(), measured.label, measured.angular_velocity.size(),
                  measured.left_out,
                  measured.thinned_out > 0
                      ? fmt::format(", {} left out by --max-points", measured.thinned_out)
                      : ""),
      model};
  for (const std::string& c : measured.conversions) lines.push_back("derived: " + c);
  return lines;
}

// The point-by-point table and the report on standard output.
void print_comparison(const Comparison& c, const std::vector<std::string>& report,
                      const std::filesystem::path& directory, const PlotOutcome& plot) {
  const MeasuredTorques& m = c.measured;
  std::cout << fmt::format("{:>14} {:>12} {:>14} {:>14} {:>8}\n", "Omega [rad/s]", "rate [1/s]",
                           "measured [N m]", "predicted", "error");
  for (std::size_t i = 0; i < c.torque.size(); ++i) {
    std::cout << fmt::format("{:>14.4e} {:>12.4g} {:>14.4e} {:>14.4e} {:>+7.1f}%\n",
                             m.angular_velocity[i], m.shear_rate[i], m.torque[i], c.torque[i],
                             100.0 * (c.torque[i] / m.torque[i] - 1.0));
  }
  for (const std::string& line : report) std::cout << line << "\n";
  std::cout << fmt::format("results: {}{}\n", (directory / "comparison.csv").string(),
                           plot.written() ? ", " + (directory / "comparison.png").string()
                                          : fmt::format(" (no plot: {})", plot.reason));
}

}  // namespace

// Reads the scene and the measured curve, solves the scene at the measured
// angular velocities (increasing: each solve warm-starts from the previous
// one) and writes comparison.csv, .h5, .png and summary.txt.
int compare(const CompareOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  dealii::ParameterHandler prm;
  auto [material, settings, entries] = read_scene_input(prm, o.scene_file, o.preset, o.material);
  const std::string scene_name = prm.get("scene");
  // The operating points are the measured ones: the scene file's sweep is not used.
  std::erase_if(entries, [](const SetEntry& e) {
    return !e.subsections.empty() && e.subsections.front() == "sweep";
  });
  check_entry_scales(entries, o.scene_file);
  std::unique_ptr<Scene> scene = make_scene(prm, material, settings, o.scene_file.parent_path());
  const MeasuredFile data = read_measured_file(o.data_file, o.reading.format);
  std::vector<std::string> file_report;
  for (const std::string& note : data.notes) file_report.push_back("measured file: " + note);
  const InstrumentConstants constants =
      instrument_constants(*scene, scene_name, o, data, file_report);
  for (const std::string& line : file_report)
    if (line.starts_with("warning: ")) std::cerr << "macro: " << line << "\n";
  const MeasuredTorques measured = read_measured(o, data, constants);
  const std::vector<SetEntry> measured_points = measured_entries(measured, o.data_file);
  entries.insert(entries.end(), measured_points.begin(), measured_points.end());
  check_derived_scales(*scene, material, settings, measured.angular_velocity, entries,
                       o.scene_file);

  const std::filesystem::path directory =
      o.output.empty() ? default_directory(o.data_file, o.scene_file) : o.output;
  ResultFolder folder(
      directory, {"comparison.csv", "summary.txt", "comparison.png", "comparison.h5"}, o.force);
  if (folder.refused()) return kExitOutputExists;
  // The number of points is known now; when ranks are to share meshes, the
  // scene is made again on its group's ranks.
  const RankGroups groups(measured.angular_velocity.size(), o.ranks_per_point);
  if (groups.ranks_per_point() > 1) {
    settings.mesh_communicator = groups.mesh_communicator();
    scene = make_scene(prm, material, settings, o.scene_file.parent_path());
  }
  std::vector<SceneResult> results = solve_operating_points(
      *scene, measured.angular_velocity, groups,
      {.settings = settings,
       .label = fmt::format("macro compare {}", o.data_file.filename().string()),
       .quiet = o.quiet});
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) return kExitOk;

  const Comparison comparison = compare_points(measured, std::move(results));
  std::vector<std::string> report = agreement_report(comparison);
  const std::string extrapolation =
      extrapolation_note(*scene, material, measured.angular_velocity);
  if (!extrapolation.empty()) report.push_back(extrapolation);
  if (!material.source.empty()) report.insert(report.begin(), "material: " + material.source);
  report.insert(report.end(), file_report.begin(), file_report.end());
  const UnitTable table = comparison_table(comparison);
  const std::vector<std::string> header_lines =
      provenance(o, scene->description(), measured, describe_model(material, settings));

  write_results_csv(folder.temporary("comparison.csv"), folder.path("comparison.csv"), header_lines,
                    table, 8);
  const PlotOutcome plot =
      write_plot(comparison, o, measured.label, folder.temporary("comparison.png"));
  if (plot.kind == PlotOutcome::Kind::write_failed) {
    throw NumericalError(
        fmt::format("cannot write '{}': {}", folder.path("comparison.png").string(), plot.reason));
  }
  if (!plot.written()) folder.discard("comparison.png");
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_summary(folder.temporary("summary.txt"), header_lines, report, wall,
                groups.ranks_per_point(), plot);
  std::ostringstream parameters;
  prm.print_parameters(parameters, dealii::ParameterHandler::Text);
  write_results_h5(folder.temporary("comparison.h5"), table,
                   {.software = header_lines[0],
                    .scene_file = o.scene_file.string(),
                    .description = fmt::format(
                        "{}\n", fmt::join(header_lines.begin() + 1, header_lines.end(), "\n")),
                    .model = describe_model(material, settings),
                    .parameters = parameters.str(),
                    .wall_time = wall,
                    .mpi_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                    .ranks_per_point = groups.ranks_per_point()});
  folder.commit();

  if (!o.quiet) print_comparison(comparison, report, directory, plot);
  if (!plot.written()) std::cerr << "macro: warning: no plot written (" << plot.reason << ")\n";
  return kExitOk;
}

}  // namespace softglass::macro::app
