// What the `bridge` subcommands share: provenance lines, whole-file writes,
// and a material's E* from where the user has it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bridge/app/commands.h"
#include "bridge/law/law.h"
#include "bridge/material/prediction.h"
#include "common/atomic_output.h"

namespace softglass::bridge {

/// The header lines of a result: its title, the command line, software and date.
std::vector<std::string> provenance(const std::string& title, const std::string& command_line);

/// `text` into `out`'s temporary file (the caller commits).
void write(AtomicOutput& out, const std::string& text);

/// Whether the law's amplitude sweep covers φ.
bool sweep_covers(const Law& law, double phi);

/// E* = 9.92 γ_i/R of an emulsion (Seth et al. 2006) from `source`'s interfacial
/// tension and radius, with its provenance line in `lines`.
double emulsion_modulus(const ModulusSource& source, std::vector<std::string>& lines);

/// The inputs of a prediction mode (bridge/material/prediction.h) from the
/// command line's: E* as given (or from γ_i and R), G′ (matched to the law's
/// static G0), and what modes (c) and (d) take.
PredictionInputs prediction_inputs(const ModulusSource& source, const ModeInputs& mode,
                                   double phi, double viscosity, bool extrapolate,
                                   std::vector<std::string>& lines);

/// E* from its source (commands.h, ModulusSource), with a provenance line in
/// `lines` (and, from a measured plateau, a printed one).
double contact_modulus(const ModulusSource& source, const Law& law, double phi, bool extrapolate,
                       std::vector<std::string>& lines);

}  // namespace softglass::bridge
