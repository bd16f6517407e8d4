// Reading the material fragment (docs/material-format.md) with deal.II's
// ParameterHandler, the parameter syntax of every softglass tool.
//
// A scene file includes the fragment (`include material.prm`); its reader calls
// declare_material() among its own declarations, parses, and calls
// read_material(). Standalone fragments are read by read_material_file().
//
// `model`, `yield stress` and the entries the model requires must be set
// (material_model.h; herschel-bulkley and its restrictions: `consistency` and
// `flow index`, also for newtonian, where they read 0 and 1: a file states its
// law in full; tabulated: `rates` and `stresses`); the N1 and N2 entries
// default to zero. The model then enforces its rules (material.h,
// tabulated_law.h). All problems raise InputError
// (exit code 2) with one line naming the entry, its value and what is allowed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/parameter_input.h"
#include "macro/material/material.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro {

/// Declares `subsection material` and its entries, documented with units and
/// allowed values.
void declare_material(dealii::ParameterHandler& prm);

/// The material parsed into `prm` (declared by declare_material), validated.
Material read_material(dealii::ParameterHandler& prm);

/// Sets the `subsection material` entries among `entries` (those of a
/// fragment file) in `prm`, so that `prm` states the material actually used (a
/// command line's --material).
void set_material(dealii::ParameterHandler& prm, const std::vector<SetEntry>& entries);

/// Parses fragment text; `source` names it in messages.
Material parse_material(const std::string& text, const std::string& source);

/// A file holding the fragment and nothing else, read like every parameter
/// file (common/parameter_input.h: includes, byte-order mark, entries set
/// twice), with the entries it sets.
struct MaterialFile {
  Material material;
  std::vector<SetEntry> entries;
};
MaterialFile read_material_file(const std::filesystem::path& file);

}  // namespace softglass::macro
