// micro: the particle engine's command line.
//
//   micro pack FILE.prm      make and relax a packing, measure Z, ε, Π, G0
//   micro run FILE.prm       pack, shear at one γ̃ until stationary, summarise
//   micro template           print a documented parameter file
//   micro summary A.h5 B.h5  average runs of one state point over packings
//
// Exit codes (common/errors.h): 0 success, 1 computation failed, 2 bad input,
// 3 output exists (use --force).
#include <fmt/format.h>
#include <omp.h>
#include <CLI/CLI.hpp>

#include <cstdio>

#include "common/errors.h"
#include "common/version.h"
#include "micro/app/commands.h"
#include "micro/app/parameter_file.h"

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "micro: error: %s\n", message.c_str());
  return code;
}

}  // namespace

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
  CLI::App* summary =
      app.add_subcommand("summary", "average run files of one state point over their packings");
  std::vector<std::filesystem::path> run_files;
  std::string csv;
  summary->add_option("run_files", run_files, "result files of `micro run` (HDF5)")->required();
  summary->add_option("--csv", csv, "also write the table as CSV");
  summary->add_flag("-f,--force", options.force, "overwrite an existing CSV file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (threads > 0) omp_set_num_threads(threads);
  if (!output.empty()) options.output = output;

  try {
    if (*tmpl) std::fputs(micro::parameter_template().c_str(), stdout);
    if (*pack) micro::pack_command(options);
    if (*run) micro::run_command(options);
    if (*summary) micro::summary_command(run_files, csv, options.force);
  } catch (const InputError& e) {
    return fail(kExitBadInput, e.what());
  } catch (const OutputExistsError& e) {
    return fail(kExitOutputExists, e.what());
  } catch (const std::exception& e) {
    return fail(kExitFailure, e.what());
  }
  return kExitOk;
}
