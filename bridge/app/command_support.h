// What the `bridge` subcommands share: provenance lines, result files beside
// a main one, whole-file writes, and a material's E* from where the user has it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bridge/app/commands.h"
#include "bridge/law/law.h"
#include "common/atomic_output.h"

namespace softglass::bridge {

/// The header lines of a result: its title, the command line, software and date.
std::vector<std::string> provenance(const std::string& title, const std::string& command_line);

/// A result file beside `main`: law.prm → law_phi.csv.
std::filesystem::path beside(const std::filesystem::path& main, const std::string& suffix);

/// `text` into `out`'s temporary file (the caller commits).
void write(AtomicOutput& out, const std::string& text);

/// Whether the law's amplitude sweep covers φ.
bool sweep_covers(const Law& law, double phi);

/// E* from its source (commands.h, ModulusSource), with a provenance line in
/// `lines` (and, from a measured plateau, a printed one).
double contact_modulus(const ModulusSource& source, const Law& law, double phi, bool extrapolate,
                       std::vector<std::string>& lines);

}  // namespace softglass::bridge
