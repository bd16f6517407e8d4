// micro: the particle engine's command line.
//
//   micro pack FILE.prm      make and relax a packing, measure Z, ε, Π, G0
//   micro run FILE.prm       pack, shear at one γ̃ until stationary, summarise
//   micro template           print a documented parameter file
//   micro analyze RUN.h5     structure of the stationary part: g(r,θ), g_lm(r), r_m, f_m Σ_m
//   micro summary A.h5 B.h5  average runs of one state point over packings
//   micro sweep FILE.prm     flow curves over φ, γ̃ and packings (MPI: mpirun -n K micro sweep …)
//   micro slip FILE.prm      particles between smooth walls: wall stress, slip velocity, profile,
//                            the plug's slip law
//   micro oscillate FILE.prm amplitude and frequency sweeps of oscillatory shear: G′, G″, LAOS
//
// Exit codes (common/errors.h): 0 success, 1 computation failed, 2 bad input,
// 3 output exists (use --force).
#include <fmt/format.h>
#include <omp.h>
#include <CLI/CLI.hpp>

#include <cstdio>

#include "common/command_line.h"
#include "common/errors.h"
#include "common/version.h"
#include "micro/app/commands.h"
#include "micro/app/oscillate_command.h"
#include "micro/app/slip_command.h"
#include "micro/app/sweep_command.h"
#include "micro/app/workers.h"
#include "micro/input/parameter_file.h"

int main(int argc, char** argv) {
  using namespace softglass;
  CLI::App app{
      "softglass micro: overdamped simulations of sheared soft particle glasses "
      "(Seth et al., Nature Materials 2011)",
      "micro"};
  app.set_version_flag("--version", fmt::format("softglass micro {} ({})", kVersion, kGitRevision));
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "OpenMP threads (default: all cores)")
      ->check(CLI::Range(1, 1024));

  micro::CommandOptions options;
  std::string output;
  const auto add_run_options = [&](CLI::App* sub) {
    sub->add_option("parameter_file", options.parameter_file, "parameter file (.prm)")->required();
    sub->add_option("-o,--output", output, "result file (HDF5); overrides the parameter file");
    sub->add_flag("-f,--force", options.force, "overwrite an existing result file");
    sub->add_flag("-q,--quiet", options.quiet, "no progress display");
  };
  CLI::App* pack = app.add_subcommand("pack", "make and relax a packing; measure Z, eps, Pi, G0");
  add_run_options(pack);
  CLI::App* run =
      app.add_subcommand("run", "pack, shear at one shear rate until stationary, summarise");
  add_run_options(run);
  CLI::App* tmpl =
      app.add_subcommand("template", "print a documented parameter file with all defaults");
  bool sweep_template = false, oscillation_template = false, slip_template = false;
  tmpl->add_flag("--sweep", sweep_template, "the template of a sweep file (micro sweep)");
  tmpl->add_flag("--oscillation", oscillation_template,
                 "the template of an oscillation file (micro oscillate)")
      ->excludes("--sweep");
  tmpl->add_flag("--slip", slip_template, "the template of a slip file (micro slip)")
      ->excludes("--sweep")
      ->excludes("--oscillation");
  CLI::App* analyze = app.add_subcommand(
      "analyze", "structure of a run's stationary part: g(r, theta), g_lm(r), r_m, f_m Sigma_m");
  micro::AnalyzeOptions analyze_options;
  double bin_width = 0.0, slab = 0.0;
  analyze->add_option("run_file", analyze_options.run_file, "result file of `micro run` (HDF5)")
      ->required();
  analyze->add_option("--csv", analyze_options.csv_prefix,
                      "also write PREFIX_harmonics.csv, PREFIX_map.csv, PREFIX_summary.csv");
  analyze
      ->add_option("--bin-width", bin_width,
                   "radial bin width of g_lm(r), units of R (default 0.02)")
      ->check(CLI::Range(1e-4, 0.5));
  analyze
      ->add_option("--slab", slab,
                   "half-width of the flow-gradient slab of g(r, theta), units of R (default 0.25)")
      ->check(CLI::Range(1e-3, 1.0));
  analyze->add_flag("-f,--force", analyze_options.force,
                    "replace an existing analysis and CSV files");
  CLI::App* summary =
      app.add_subcommand("summary", "average run files of one state point over their packings");
  std::vector<std::filesystem::path> run_files;
  std::string csv;
  summary->add_option("run_files", run_files, "result files of `micro run` (HDF5)")->required();
  summary->add_option("--csv", csv, "also write the table as CSV");
  summary->add_flag("-f,--force", options.force, "overwrite an existing CSV file");

  CLI::App* slip = app.add_subcommand(
      "slip", "particles sheared between two smooth walls: wall stress, slip velocity, velocity "
              "profile per apparent rate, and the sliding plug's slip law (plug_slip.csv; "
              "docs/physics.md, 'Wall slip'); resumable");
  slip->add_option("parameter_file", options.parameter_file,
                   "slip file: a run's parameters plus subsection 'walls'")
      ->required();
  slip->add_flag("-f,--force", options.force, "redo runs whose files exist");
  slip->add_flag("-q,--quiet", options.quiet, "no progress lines");

  // The commands that run a sweep of cases share their options (sweep_work.h).
  micro::SweepOptions sweep_options, oscillate_options;
  std::size_t only_case = 0;
  const auto add_sweep = [&](const char* name, const char* what, const char* file,
                             micro::SweepOptions& o) {
    CLI::App* sub = app.add_subcommand(name, what);
    sub->add_option("parameter_file", o.parameter_file, file)->required();
    sub->add_flag("--list", o.list, "print the cases and whether they are done; run nothing");
    sub->add_flag("--gather", o.gather_only, "only rebuild the tables from the finished runs");
    sub->add_option("--case", only_case,
                    "run case K alone (and its packing if missing): one task of a batch array "
                    "job; see --list");
    sub->add_flag("-q,--quiet", o.quiet, "no progress bar (the log lines stay)");
    return sub;
  };
  CLI::App* sweep = add_sweep("sweep",
                              "flow curves: packings, then every (phi, gamma~, seed) case, then "
                              "the flow-curve table; resumable (finished files are skipped), one "
                              "sweep per folder",
                              "sweep file: a run's parameters plus subsection 'sweep'",
                              sweep_options);
  CLI::App* oscillate =
      add_sweep("oscillate",
                "oscillatory shear: amplitude and frequency sweeps (G', G'', I3/I1, Chebyshev "
                "coefficients) over packings; resumable like sweep",
                "oscillation file: a run's parameters plus subsection 'oscillation'",
                oscillate_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_command_line_error("micro", app, e);
  }
  if (threads > 0) omp_set_num_threads(threads);
  if (!output.empty()) options.output = output;
  for (auto [sub, o] : {std::pair(sweep, &sweep_options), std::pair(oscillate, &oscillate_options)})
    if (sub->count("--case") > 0) o->only_case = only_case;
  for (int k = 0; k < argc; ++k)
    sweep_options.command_line += (k ? " " : "") + std::string(argv[k]);
  oscillate_options.command_line = sweep_options.command_line;
  const micro::Workers workers;

  return run_reporting_errors("micro", [&] {
    if (*tmpl)
      std::fputs(micro::parameter_template(sweep_template         ? micro::TemplateKind::sweep
                                           : oscillation_template ? micro::TemplateKind::oscillation
                                           : slip_template        ? micro::TemplateKind::slip
                                                                  : micro::TemplateKind::run)
                     .c_str(),
                 stdout);
    if (*pack) micro::pack_command(options);
    if (*run) micro::run_command(options);
    if (*summary) micro::summary_command(run_files, csv, options.force);
    if (*slip) micro::slip_command(options);
    if (*sweep) micro::sweep_command(sweep_options, workers);
    if (*oscillate) micro::oscillate_command(oscillate_options, workers);
    if (*analyze) {
      if (bin_width > 0.0) analyze_options.bin_width = bin_width;
      if (slab > 0.0) analyze_options.slab = slab;
      micro::analyze_command(analyze_options);
    }
    return int(kExitOk);
  });
}
