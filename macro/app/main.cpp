// macro: finite elements of rheometers and channels for a Herschel-Bulkley law.
//
//   macro run FILE.prm [-o DIR] [--preset fast|standard|accurate] [--force] [--quiet]
//   macro compare FILE.prm DATA.csv [-o DIR] [--sample S] ...
//                           predicted against measured torques, point by point
//   macro template          a documented scene file with every entry and default
//   mpirun -n N macro run|compare ...  operating points over N ranks (--ranks-per-point)
//
// Exit codes (common/errors.h): 0 success, 1 computation failed, 2 bad input,
// 3 output exists (use --force).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "common/command_line.h"
#include "common/errors.h"
#include "common/mpi_launch.h"
#include "common/version.h"
#include "macro/app/compare.h"
#include "macro/app/run.h"

namespace {

using softglass::positive;

// `macro run`: its options into `options`.
void add_run_command(CLI::App& app, softglass::macro::app::RunOptions& options) {
  CLI::App* run =
      app.add_subcommand("run", "solve a scene file over its sweep of operating points");
  run->add_option("scene", options.scene_file, "scene file (.prm)")->required();
  run->add_option("-o,--output", options.output,
                  "output directory (default: <scene stem>_results)");
  run->add_option("--preset", options.preset,
                  "override the file's solver preset: fast | standard | accurate");
  run->add_option("--material", options.material,
                  "material fragment (.prm, e.g. from `bridge material`) replacing the scene's");
  run->add_option("--ranks-per-point", options.ranks_per_point,
                  "MPI ranks that share each operating point's mesh (default: the points are "
                  "spread over the ranks first, the ranks shared out when points are fewer)")
      ->check(positive);
  run->add_flag("-f,--force", options.force, "overwrite existing results");
  run->add_flag("-q,--quiet", options.quiet, "no progress display");
}

// `macro compare`: its options into `compare_options`.
void add_compare_command(CLI::App& app, softglass::macro::app::CompareOptions& compare_options) {
  CLI::App* compare = app.add_subcommand(
      "compare",
      "predict the torques (and normal forces) of a measured rheometer curve with a scene file "
      "and compare them point by point");
  compare
      ->add_option("scene", compare_options.scene_file,
                   "scene file (.prm) of the instrument: couette, cone-plate or parallel-plates")
      ->required();
  compare
      ->add_option("data", compare_options.data_file,
                   "measured curve: torque or stress against angular velocity or shear rate, "
                   "as the instrument exported it (docs/measured-files.md)")
      ->required();
  compare->add_option("-o,--output", compare_options.output,
                      "output directory (default: <data stem>_vs_<scene stem>)");
  compare->add_option("--sample", compare_options.sample,
                      "the curve to compare when the file holds several (its label)");
  compare->add_option("--min-rate", compare_options.min_rate,
                      "compare only points from this shear rate [1/s]");
  compare->add_option("--max-rate", compare_options.max_rate,
                      "compare only points up to this shear rate [1/s]");
  compare->add_option("--strain-constant", compare_options.strain_constant,
                      "the instrument's shear rate per angular velocity [1/rad] (default: the "
                      "geometry's standard conversion)");
  compare->add_option("--stress-constant", compare_options.stress_constant,
                      "the instrument's stress per torque [Pa/(N m)] (default: the geometry's "
                      "standard conversion)");
  softglass::add_measured_format_option(*compare, compare_options.reading.format, "the measured curve");
  compare->add_option("--rate-unit", compare_options.reading.rate,
                      "units of shear-rate columns without units (1/s, 1/min)");
  compare->add_option("--stress-unit", compare_options.reading.stress,
                      "units of stress columns without units (Pa, kPa, MPa, mPa)");
  compare->add_option("--preset", compare_options.preset,
                      "override the file's solver preset: fast | standard | accurate");
  compare->add_option("--material", compare_options.material,
                      "material fragment (.prm, e.g. from `bridge material`) replacing the "
                      "scene's");
  compare->add_option(
      "--max-points", compare_options.max_points,
      fmt::format("compare at most N of the points in the rate window, evenly spaced, the first "
                  "and last kept (default: all; more than {} are refused)",
                  softglass::macro::app::kMostComparedPoints));
  compare
      ->add_option("--ranks-per-point", compare_options.ranks_per_point,
                   "MPI ranks that share each operating point's mesh (default: as for run)")
      ->check(positive);
  compare->add_flag("-f,--force", compare_options.force, "overwrite existing results");
  compare->add_flag("-q,--quiet", compare_options.quiet, "no progress display and no table");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace softglass;
  // MPI (a no-op without mpirun): sweeps are split over groups of ranks, each
  // group sharing its points' meshes (operating_points.h).
  prefer_lean_mpi_singleton();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  CLI::App app{
      "softglass macro: steady creeping flow of a yield-stress material (Herschel-Bulkley or a "
      "tabulated flow curve) in rheometers, channels, pipes and ducts (deal.II finite elements)",
      "macro"};
  app.set_version_flag("--version", fmt::format("softglass macro {} ({})", kVersion, kGitRevision));
  app.require_subcommand(1);
  macro::app::RunOptions options;
  add_run_command(app, options);
  macro::app::CompareOptions compare_options;
  add_compare_command(app, compare_options);
  app.add_subcommand("template", "print a documented scene file with every entry");

  // Exceptions from deal.II's own checks should not print their backtraces.
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return report_command_line_error("macro", app, error);
  }
  return run_reporting_errors("macro", [&] {
    if (app.got_subcommand("template")) {
      macro::app::print_template();
      return int(kExitOk);
    }
    if (app.got_subcommand("compare")) return macro::app::compare(compare_options);
    return macro::app::run(options);
  });
}
