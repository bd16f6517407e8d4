// The parameter file of `micro pack` and `micro run` (deal.II ParameterHandler
// syntax, shared with every softglass tool). `micro template` prints it with
// every entry documented: meaning, units, default and allowed range.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "micro/analysis/structure.h"
#include "micro/contact/contact_law.h"
#include "micro/dynamics/integrator.h"
#include "micro/model/overdamped_shear.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"
#include "micro/protocol/wall_run.h"
#include "micro/sweep/oscillation_plan.h"
#include "micro/sweep/sweep_plan.h"

namespace softglass::micro {

struct MicroParameters {
  PackingSpec packing;
  std::filesystem::path packing_input;  // reuse the packing of an earlier run file
  ContactLawSpec contact_law;
  ShearModel shear_model;
  ShearProtocol protocol;
  IntegratorSpec integrator;
  StructureSettings structure;
  std::filesystem::path output_file = "micro.h5";
  bool overwrite = false;

  /// The full parameter set as a parameter file (defaults included).
  std::string text;
};

/// Reads `file`. Unknown entries, unparsable values, values outside their range
/// and inconsistent combinations raise InputError naming the entry. Input file
/// names in it are taken relative to the parameter file's directory.
MicroParameters read_parameter_file(const std::filesystem::path& file);

/// A sweep file: a parameter file for every case plus a `sweep` subsection.
struct SweepParameters {
  MicroParameters base;
  SweepSpec spec;
};
SweepParameters read_sweep_file(const std::filesystem::path& file);

/// A slip file (`micro slip`): a parameter file plus a `walls` subsection —
/// particles sheared between two smooth walls (docs/physics.md, "Wall slip")
/// at each apparent rate, for each packing.
struct SlipSpec {
  std::vector<double> apparent_rates{1e-5};  // γ̃_app, each a run's γ̃
  SolventReference solvent = SolventReference::local_mean;  // model/solvent_flow.h
  unsigned packings = 1, first_seed = 1;
  WallRunSpec run;
  std::filesystem::path directory = "slip";
};
struct SlipParameters {
  MicroParameters base;
  SlipSpec spec;
};
SlipParameters read_slip_file(const std::filesystem::path& file);

/// What a sweep sets in each case's parameters.
struct SweepCaseSettings {
  std::size_t particles;
  double volume_fraction, gamma_tilde;
  unsigned seed;
  std::optional<RunLength> run;         // the preset's; none: keep the file's
  std::filesystem::path packing_input;  // empty: make the packing
  std::filesystem::path output;
};
/// `base` with the case's entries set, checked, and its text (a valid
/// `micro run` file) updated.
MicroParameters case_parameters(const MicroParameters& base, const SweepCaseSettings& settings);

/// An oscillation file (`micro oscillate`): a parameter file for every case
/// plus an `oscillation` subsection. The case's γ̃ is its peak rate γ0 ω̃;
/// subsection `shear`'s run length does not apply (the oscillation's does).
struct OscillationParameters {
  MicroParameters base;
  OscillationSpec spec;
};
OscillationParameters read_oscillation_file(const std::filesystem::path& file);

/// The documented template with all defaults: of a run file, or of a sweep or
/// an oscillation file (the same plus subsection `sweep` or `oscillation`).
enum class TemplateKind { run, sweep, oscillation, slip };
std::string parameter_template(TemplateKind kind = TemplateKind::run);

}  // namespace softglass::micro
