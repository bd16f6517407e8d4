// The parameter file of `micro pack` and `micro run` (deal.II ParameterHandler
// syntax, shared with every softglass tool). `micro template` prints it with
// every entry documented: meaning, units, default and allowed range.
#pragma once

#include <filesystem>
#include <string>

#include "micro/analysis/structure.h"
#include "micro/contact/contact_law.h"
#include "micro/dynamics/integrator.h"
#include "micro/dynamics/overdamped_shear.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"

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

/// The documented template with all defaults.
std::string parameter_template();

}  // namespace softglass::micro
