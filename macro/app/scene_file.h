// The scene file: a deal.II ParameterHandler file holding `set scene`, the
// scene's subsection, `subsection solver`, `subsection sweep`, `subsection
// output` and (usually by `include FILE`) the material fragment.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <string>
#include <vector>

#include "common/parameter_input.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/material.h"

namespace softglass::macro::app {

/// Declares every entry a scene file may hold.
void declare_scene_file(dealii::ParameterHandler& prm);

/// Parses the scene file into `prm`, each `include FILE` line replaced by that
/// file's text (FILE relative to the including file); a missing file, unknown
/// entries, values that do not match their pattern (e.g. a unit written after
/// a number) → InputError naming the file, line and entry.
/// An entry of a scene other than the one `scene` chooses is refused (it would
/// be ignored in silence: pressure gradients read as angular velocities).
/// Returns the entries the file sets, with their files and lines.
std::vector<SetEntry> parse_scene_file(dealii::ParameterHandler& prm,
                                       const std::filesystem::path& file);

/// What every command takes from a scene file: declares and parses it into
/// `prm` with the command line's overrides (`preset`, a `material` fragment;
/// empty: none), and reads the material and the solver settings.
struct SceneInput {
  Material material;
  fe::SolverSettings settings;
  /// What the files set, where (a --material fragment's entries in place of
  /// the scene's material): to name a value whose consequences are refused.
  std::vector<SetEntry> entries;
};
SceneInput read_scene_input(dealii::ParameterHandler& prm, const std::filesystem::path& file,
                            const std::string& preset, const std::filesystem::path& material);

/// The operating points of `subsection sweep`, validated (> 0, finite).
std::vector<double> read_sweep(dealii::ParameterHandler& prm);

}  // namespace softglass::macro::app
