// Material models: what `set model = …` in a material fragment may name, one
// model per file in models/, registered (common/registry.h) in
// models/registered_material_models.h with one line each.
//
// A model declares the entries of `subsection material` it reads (entries of
// the same name in several models are declared alike, so they may share
// them), names those a file must set for it, and makes the Material from
// them. The fragment's reader (material_parameters.h) declares every model's
// entries, picks the model the file names and lets it read.
#pragma once

#include <string>
#include <vector>

#include "common/registry.h"
#include "macro/material/material.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro {

struct MaterialModelTraits {
  /// Declares the model's entries inside `subsection material`.
  void (*declare)(dealii::ParameterHandler& prm) = nullptr;
  /// The entries a file must set for this model (besides `model`).
  std::vector<std::string> required;
};

/// `make` reads the material inside `subsection material` of a parsed handler
/// and validates it (InputError naming the entry otherwise).
using MaterialModelEntry = ComponentEntry<Material, dealii::ParameterHandler, MaterialModelTraits>;

/// Every model (models/registered_material_models.h).
const Registry<MaterialModelEntry>& material_models();

}  // namespace softglass::macro
