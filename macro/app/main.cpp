// macro: finite elements of rheometers and channels for a Herschel-Bulkley law.
//
//   macro run FILE.prm [-o DIR] [--preset fast|standard|accurate] [--force] [--quiet]
//   macro template          a documented scene file with every entry and default
//   mpirun -n N macro run ...  the sweep's operating points split over N ranks
//
// Exit codes (common/errors.h): 0 success, 1 computation failed, 2 bad input,
// 3 output exists (use --force).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "common/errors.h"
#include "common/version.h"
#include "macro/app/run.h"

int main(int argc, char** argv) {
  using namespace softglass;
  // MPI (a no-op without mpirun): sweeps are split over the ranks (run.cpp).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  CLI::App app{
      "softglass macro: steady creeping flow of a Herschel-Bulkley material in rheometers, "
      "channels, pipes and ducts (deal.II finite elements)",
      "macro"};
  app.set_version_flag("--version", fmt::format("softglass macro {} ({})", kVersion, kGitRevision));
  app.require_subcommand(1);
  macro::app::RunOptions options;
  CLI::App* run =
      app.add_subcommand("run", "solve a scene file over its sweep of operating points");
  run->add_option("scene", options.scene_file, "scene file (.prm)")->required();
  run->add_option("-o,--output", options.output,
                  "output directory (default: <scene stem>_results)");
  run->add_option("--preset", options.preset,
                  "override the file's solver preset: fast | standard | accurate");
  run->add_flag("-f,--force", options.force, "overwrite existing results");
  run->add_flag("-q,--quiet", options.quiet, "no progress display");
  app.add_subcommand("template", "print a documented scene file with every entry");

  // Exceptions from deal.II's own checks should not print their backtraces.
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  return run_reporting_errors("macro", [&] {
    if (app.got_subcommand("template")) {
      macro::app::print_template();
      return int(kExitOk);
    }
    return macro::app::run(options);
  });
}
