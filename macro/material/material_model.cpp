#include "macro/material/material_model.h"

#include "macro/material/models/registered_material_models.h"

namespace softglass::macro {

#define SOFTGLASS_DECLARE_MODEL(name) MaterialModelEntry name##_model();
SOFTGLASS_MATERIAL_MODELS(SOFTGLASS_DECLARE_MODEL)
#undef SOFTGLASS_DECLARE_MODEL

const Registry<MaterialModelEntry>& material_models() {
#define SOFTGLASS_LIST_MODEL(name) name##_model(),
  static const Registry<MaterialModelEntry> registry(
      "material: model", {SOFTGLASS_MATERIAL_MODELS(SOFTGLASS_LIST_MODEL)});
#undef SOFTGLASS_LIST_MODEL
  return registry;
}

}  // namespace softglass::macro
