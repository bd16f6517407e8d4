// bridge: from simulated flow curves to the universal law and to materials.
//
//   bridge fit TABLE.csv [--packings RUNS.csv] [--structure STRUCTURE.csv]
//                                                 Herschel-Bulkley and universal-law fits
//   bridge material LAW.prm --phi … --modulus … --viscosity …
//                                                 a material fragment for the continuum
//   bridge predict LAW.prm --phi … --viscosity … (E* | G' | yield stress | a curve) --rates …
//                                                 a predicted flow curve with bands, four modes
//   bridge amplitude-sweep LAW.prm --phi … --plateau-modulus … --viscosity … [--data SWEEP.csv]
//                                                 a material's amplitude sweep, against a measured
//                                                 one
//   bridge slip-law SLIP.csv [--below-yield LAW.prm | --max-stress S]
//                  [--modulus … --viscosity … --radius … [--phi …] [-o slip.prm]]
//                                                 the wall slip law of a `micro slip` table, and
//                                                 the macro `subsection slip` in SI
//   bridge rescale DATA.csv --viscosity … (--yield-strain … | --shear-modulus … |
//                  --law LAW.prm --phi …)
//                                                 measured curves on the universal curve
//
// Exit codes (common/errors.h): 0 success, 1 computation failed, 2 bad input,
// 3 output exists (use --force).
#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <tuple>

#include "bridge/app/commands.h"
#include "common/command_line.h"
#include "common/errors.h"
#include "common/version.h"

namespace {

std::string joined(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace softglass;
  using namespace softglass::bridge;
  CLI::App app{
      "softglass bridge: Herschel-Bulkley and universal-law fits of simulated flow curves, "
      "materials for the continuum, measured curves on the universal law (Seth et al., Nature "
      "Materials 2011)",
      "bridge"};
  app.set_version_flag("--version",
                       fmt::format("softglass bridge {} ({})", kVersion, kGitRevision));
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "OpenMP threads for the bootstrap (default: all cores)")
      ->check(CLI::Range(1, 1024));

  FitOptions fit;
  CLI::App* fit_cmd = app.add_subcommand(
      "fit",
      "fit a flow-curve table (docs/flow-curve-format.md): per-phi Herschel-Bulkley laws, "
      "yield strains, the universal k, k', k'' with bootstrap errors; writes a law file and "
      "CSV tables");
  auto* fit_table = fit_cmd->add_option("table", fit.table, "flow-curve table (CSV)");
  auto* fit_law = fit_cmd->add_option(
      "--law", fit.law,
      "instead of a flow-curve table, the flow laws of this law file, kept as they are, with "
      "the amplitude-sweep law of --oscillation added (or replaced)");
  fit_law->excludes(fit_table);
  auto* fit_packings = fit_cmd->add_option(
      "--packings", fit.packings,
      "its per-packing companion (CSV): errors from a packing bootstrap; without "
      "it, a parametric bootstrap from the table's standard errors");
  auto* fit_structure =
      fit_cmd->add_option("--structure", fit.structure,
                          "structure table (CSV: phi, gamma_tilde, f_m, f_m_se) for the force law, "
                          "when the flow-curve table has no f_m columns");
  fit_law->excludes(fit_packings)->excludes(fit_structure);
  fit_cmd->add_option("--oscillation", fit.oscillation,
                      "oscillation table of `micro oscillate` (CSV): adds the amplitude-sweep law "
                      "(G', G'' against gamma0, plateau, softening and crossover strains)");
  fit_cmd
      ->add_option("--oscillation-frequency", fit.oscillation_frequency,
                   "which frequency omega~ of the oscillation table, when it holds several")
      ->check(positive);
  auto* fit_min_rate =
      fit_cmd
          ->add_option("--min-rate", fit.rates.lowest,
                       "fit only the state points from this gamma~ on (the quasi-static rows "
                       "stay): the exponent depends on the window, so compare a measured "
                       "curve's over its own")
          ->check(positive);
  auto* fit_max_rate =
      fit_cmd->add_option("--max-rate", fit.rates.highest, "fit only up to this gamma~")
          ->check(positive);
  fit_law->excludes(fit_min_rate)->excludes(fit_max_rate);
  fit_cmd->add_option("-o,--output", fit.output, "law file (.prm); tables beside it")
      ->capture_default_str();
  fit_cmd->add_option("--bootstrap", fit.replicates, "bootstrap replicates")
      ->capture_default_str()
      ->check(CLI::Range(20, 1000000));
  fit_cmd->add_option("--seed", fit.seed, "seed of the bootstrap")->capture_default_str();
  fit_cmd->add_flag("-f,--force", fit.force, "overwrite existing results");
  fit_cmd->add_flag("-q,--quiet", fit.quiet, "no progress display");

  MaterialOptions material;
  CLI::App* material_cmd =
      app.add_subcommand("material",
                         "the Herschel-Bulkley material (docs/material-format.md) of a law file at "
                         "volume fraction phi, contact modulus E* and solvent viscosity eta_s");
  material_cmd->add_option("law", material.law, "law file of `bridge fit` (.prm)")->required();
  material_cmd->add_option("--phi", material.phi, "volume fraction")
      ->required()
      ->check(CLI::Range(0.0, 1.0));
  auto* modulus =
      material_cmd->add_option("--modulus", material.source.modulus, "contact modulus E* [Pa]")
          ->check(positive);
  auto* tension = material_cmd
                      ->add_option("--interfacial-tension", material.source.interfacial_tension,
                                   "emulsions: interfacial tension gamma_i [N/m], with --radius: "
                                   "E* = 9.92 gamma_i / R")
                      ->check(positive);
  auto* radius =
      material_cmd->add_option("--radius", material.source.radius, "mean droplet radius R [m]")
          ->check(positive);
  auto* plateau =
      material_cmd
          ->add_option("--plateau-modulus", material.source.plateau_modulus,
                       "measured linear shear modulus G' [Pa] (amplitude-sweep plateau): "
                       "E* = G' / (G0/E*)(phi) with the law's static G0, or G' / (G' "
                       "plateau/E*)(phi) with its amplitude sweep (--plateau-source)")
          ->check(positive);
  material_cmd
      ->add_option("--plateau-source", material.source.plateau_source,
                   "what a measured G' plateau is matched to: static (the law's G0, the flow-curve "
                   "route) or amplitude-sweep (the plateau of its amplitude sweep)")
      ->check(CLI::IsMember({"static", "amplitude-sweep"}))
      ->capture_default_str()
      ->needs(plateau);
  tension->needs(radius);
  radius->needs(tension);
  modulus->excludes(tension);
  plateau->excludes(modulus);
  plateau->excludes(tension);
  material_cmd->add_option("--viscosity", material.viscosity, "solvent viscosity eta_s [Pa s]")
      ->required()
      ->check(positive);
  material_cmd
      ->add_option("--frequency", material.frequency,
                   "angular frequency of your amplitude sweep [rad/s]: set against the one the "
                   "law's amplitude sweep holds at for this E* and eta_s, and the crossover "
                   "strain the flow law implies there")
      ->check(positive);
  material_cmd->add_option("-o,--output", material.output,
                           "material file (.prm); default: print it");
  material_cmd->add_flag("--extrapolate", material.extrapolate,
                         "allow phi outside the simulated range (linear extrapolation)");
  material_cmd->add_flag("-f,--force", material.force, "overwrite an existing material file");
  material_cmd->add_flag("--tabulated", material.tabulated,
                         "the simulated flow curve point by point (model tabulated, from the "
                         "LAW_points.csv and LAW_phi.csv `bridge fit` writes) instead of the "
                         "Herschel-Bulkley summary");
  material_cmd
      ->add_option("--yield-stress", material.mode.yield_stress,
                   "with --tabulated: a measured yield stress [Pa] (mode c, docs/bridge.md)")
      ->check(positive);
  auto* fit_to = material_cmd->add_option(
      "--fit-to", material.mode.fit_to,
      "with --tabulated: a measured flow curve (CSV) to fit E* to (mode d)");
  material_cmd->add_option("--fit-curve", material.mode.fit_curve, "the curve of --fit-to, by label");
  add_measured_format_option(*material_cmd, material.mode.units.format, "--fit-to's file");
  material_cmd->add_option("--rate-unit", material.mode.units.rate, "units of --fit-to's rates");
  material_cmd->add_option("--stress-unit", material.mode.units.stress, "units of --fit-to's stresses");
  fit_to->excludes(modulus);
  fit_to->excludes(plateau);
  fit_to->excludes(tension);

  AmplitudeSweepOptions sweep;
  CLI::App* sweep_cmd = app.add_subcommand(
      "amplitude-sweep",
      "a material's amplitude sweep (G', G'' against the strain amplitude, in Pa) from a law "
      "file's, and, with --data, compared with a measured one point by point");
  sweep_cmd->add_option("law", sweep.law, "law file of `bridge fit --oscillation` (.prm)")
      ->required();
  sweep_cmd->add_option("--phi", sweep.phi, "volume fraction")
      ->required()
      ->check(CLI::Range(0.0, 1.0));
  auto* sweep_modulus =
      sweep_cmd->add_option("--modulus", sweep.source.modulus, "contact modulus E* [Pa]")
          ->check(positive);
  auto* sweep_plateau =
      sweep_cmd
          ->add_option("--plateau-modulus", sweep.source.plateau_modulus,
                       "measured G' plateau [Pa]: E* = G' / (G0/E*)(phi), or G' / (G' "
                       "plateau/E*)(phi) (--plateau-source)")
          ->check(positive);
  sweep_cmd
      ->add_option("--plateau-source", sweep.source.plateau_source,
                   "what a measured G' plateau is matched to: static (the law's G0, the flow-curve "
                   "route) or amplitude-sweep (the plateau of the law's amplitude sweep)")
      ->check(CLI::IsMember({"static", "amplitude-sweep"}))
      ->capture_default_str()
      ->needs(sweep_plateau);
  auto* sweep_tension =
      sweep_cmd
          ->add_option("--interfacial-tension", sweep.source.interfacial_tension,
                       "emulsions: gamma_i [N/m], with --radius: E* = 9.92 gamma_i / R")
          ->check(positive);
  auto* sweep_radius =
      sweep_cmd->add_option("--radius", sweep.source.radius, "mean droplet radius R [m]")
          ->check(positive);
  sweep_tension->needs(sweep_radius);
  sweep_radius->needs(sweep_tension);
  sweep_modulus->excludes(sweep_tension);
  sweep_plateau->excludes(sweep_modulus);
  sweep_plateau->excludes(sweep_tension);
  sweep_cmd->add_option("--viscosity", sweep.viscosity, "solvent viscosity eta_s [Pa s]")
      ->required()
      ->check(positive);
  sweep_cmd->add_option("--data", sweep.data,
                        "measured amplitude sweep as the instrument exported it: strain "
                        "amplitude, storage and loss modulus, optionally angular frequency "
                        "(docs/measured-files.md)");
  add_measured_format_option(*sweep_cmd, sweep.format, "--data");
  sweep_cmd->add_option("--sample", sweep.sample, "the curve of --data when it holds several");
  sweep_cmd
      ->add_option("-o,--output", sweep.output,
                   "folder: amplitude_sweep.csv, and with --data comparison.csv and .png")
      ->capture_default_str();
  sweep_cmd->add_flag("--extrapolate", sweep.extrapolate,
                      "allow phi outside the amplitude sweep's volume fractions");
  sweep_cmd->add_flag("-f,--force", sweep.force, "overwrite existing results");

  SlipLawOptions slip;
  CLI::App* slip_cmd = app.add_subcommand(
      "slip-law",
      "fit the wall slip law V~ gamma~ = A sigma~_w^p of a `micro slip` table per volume fraction "
      "(weighted least squares in log-log); with --modulus, --viscosity and --radius, the macro "
      "`subsection slip` (power-law, beta = A R E*^(1-p) / eta_s) at phi");
  slip_cmd->add_option("table", slip.table, "slip table of `micro slip` (slip.csv)")->required();
  slip_cmd
      ->add_option("--below-yield", slip.below_yield,
                   "law file of `bridge fit`: fit only rows whose wall stress lies below the "
                   "law's yield stress at their phi (the sliding plug a rheometer sees below "
                   "yield)");
  slip_cmd->add_option("--max-stress", slip.max_stress, "fit only rows with wall stress <= this [E*]")
      ->check(positive);
  slip_cmd->add_option("--phi", slip.phi, "volume fraction of the SI law (default: the table's, if one)")
      ->check(CLI::Range(0.0, 1.0));
  auto* slip_modulus =
      slip_cmd->add_option("--modulus", slip.modulus, "contact modulus E* [Pa]")->check(positive);
  auto* slip_viscosity = slip_cmd
                             ->add_option("--viscosity", slip.viscosity,
                                          "solvent viscosity eta_s [Pa s]")
                             ->check(positive);
  auto* slip_radius =
      slip_cmd
          ->add_option("--radius", slip.radius,
                       "particle (droplet) radius R [m]: beta is proportional to it")
          ->check(positive);
  for (CLI::Option* a : {slip_modulus, slip_viscosity, slip_radius})
    for (CLI::Option* b : {slip_modulus, slip_viscosity, slip_radius})
      if (a != b) a->needs(b);
  slip_cmd->add_option("-o,--output", slip.output,
                       "slip-law fragment (.prm) for scene files; default: print it");
  slip_cmd->add_flag("--extrapolate", slip.extrapolate,
                     "allow phi outside the table's volume fractions (stated in the file)");
  slip_cmd->add_flag("-f,--force", slip.force, "overwrite an existing slip-law file");

  RescaleOptions rescale;
  RescaleSettings& s = rescale.settings;
  CLI::App* rescale_cmd =
      app.add_subcommand("rescale",
                         "put measured flow curves (CSV with units) on the universal curve; fit E* "
                         "(and tau_y) when unknown");
  rescale_cmd->add_option("data", rescale.data,
                          "measured flow curves, as the instrument exported them "
                          "(docs/measured-files.md)")
      ->required();
  rescale_cmd->add_option("--viscosity", s.viscosity, "solvent viscosity eta_s [Pa s]")
      ->required()
      ->check(positive);
  auto* rescale_modulus =
      rescale_cmd->add_option("--modulus", s.modulus, "contact modulus E* [Pa]; fitted when absent")
          ->check(positive);
  rescale_cmd
      ->add_flag("--shared-modulus", s.shared_modulus,
                 "fit one E* for all curves (the same particles at several phi or temperatures)")
      ->excludes(rescale_modulus);
  auto* strain = rescale_cmd
                     ->add_option("--yield-strain", s.yield_strain,
                                  "yield strain gamma_y: one value, or one per curve")
                     ->delimiter(',');
  auto* shear = rescale_cmd
                    ->add_option("--shear-modulus", s.shear_modulus,
                                 "measured G0 [Pa] instead (gamma_y = tau_y/G0): one, or one per "
                                 "curve")
                    ->delimiter(',');
  strain->excludes(shear);
  rescale_cmd
      ->add_option("--yield-stress", s.yield_stress,
                   "yield stress tau_y [Pa]: one, or one per curve; fitted when absent")
      ->delimiter(',');
  rescale_cmd->add_option("--law", rescale.law,
                          "law file of `bridge fit` for k and k' (default: the paper's 80 and 20)");
  auto* phi_list = rescale_cmd
                       ->add_option("--phi", rescale.phi,
                                    "volume fraction of each curve: gamma_y from the law (--law)")
                       ->delimiter(',');
  auto* phi_labels = rescale_cmd->add_flag("--phi-from-labels", rescale.phi_from_labels,
                                           "the curve labels are their volume fractions: gamma_y "
                                           "from the law (--law)");
  phi_list->excludes(phi_labels);
  phi_list->excludes(strain);
  phi_list->excludes(shear);
  phi_labels->excludes(strain);
  phi_labels->excludes(shear);
  rescale_cmd->add_flag("--extrapolate", rescale.extrapolate,
                        "allow --phi outside the law's simulated range");
  rescale_cmd->add_option("--min-rate", s.min_rate, "fit only rates from here [1/s]");
  rescale_cmd->add_option("--max-rate", s.max_rate, "fit only rates up to here [1/s]");
  add_measured_format_option(*rescale_cmd, rescale.units.format, "the measured file");
  rescale_cmd->add_option("--rate-unit", rescale.units.rate,
                          "units of shear-rate columns without units (1/s, 1/min)");
  rescale_cmd->add_option("--stress-unit", rescale.units.stress,
                          "units of stress columns without units (Pa, kPa, MPa, mPa)");
  rescale_cmd->add_option("-o,--output", rescale.output, "rescaled points (CSV); curves beside it")
      ->capture_default_str();
  rescale_cmd->add_flag("-f,--force", rescale.force, "overwrite existing results");

  PredictOptions predict;
  CLI::App* predict_cmd = add_predict_command(app, predict);

  try {
    app.parse(argc, argv);
    if (*fit_cmd && fit.table.empty() && fit.law.empty())
      throw CLI::ValidationError("fit: give a flow-curve table, or --law with --oscillation");
    if (*fit_cmd && !fit.law.empty() && fit.oscillation.empty())
      throw CLI::ValidationError("fit: --law only adds an amplitude sweep: give --oscillation");
    if (*slip_cmd && !slip.output.empty() && !slip.modulus)
      throw CLI::ValidationError(
          "slip-law: -o writes the macro slip law: give --modulus, --viscosity and --radius");
    for (const auto& [cmd, source, name] :
         {std::tuple(material_cmd, &material.source, "material"),
          std::tuple(sweep_cmd, &sweep.source, "amplitude-sweep")}) {
      if (*cmd && !source->modulus && !source->interfacial_tension && !source->plateau_modulus &&
          material.mode.fit_to.empty())
        throw CLI::ValidationError(fmt::format(
            "{}: give --modulus, --plateau-modulus, or --interfacial-tension and --radius", name));
    }
  } catch (const CLI::ParseError& e) {
    return report_command_line_error("bridge", app, e);
  }
  if (threads > 0) omp_set_num_threads(threads);

  const std::string command_line = joined(argc, argv);
  return run_reporting_errors("bridge", [&] {
    if (*fit_cmd) fit_command(fit, command_line);
    if (*material_cmd) material_command(material, command_line);
    if (*predict_cmd) predict_command(predict, command_line);
    if (*rescale_cmd) rescale_command(rescale, command_line);
    if (*sweep_cmd) amplitude_sweep_command(sweep, command_line);
    if (*slip_cmd) slip_law_command(slip, command_line);
    return int(kExitOk);
  });
}
