#include "macro/scenes/scene.h"

#include <deal.II/base/parameter_handler.h>

#include "macro/scenes/registered_scenes.h"

namespace softglass::macro {

using dealii::ParameterHandler;

#define SOFTGLASS_DECLARE_SCENE(name) SceneEntry name##_scene();
SOFTGLASS_SCENES(SOFTGLASS_DECLARE_SCENE)
#undef SOFTGLASS_DECLARE_SCENE

const Registry<SceneEntry>& scenes() {
#define SOFTGLASS_LIST_SCENE(name) name##_scene(),
  static const Registry<SceneEntry> registry("scene", {SOFTGLASS_SCENES(SOFTGLASS_LIST_SCENE)});
#undef SOFTGLASS_LIST_SCENE
  return registry;
}

void declare_scenes(ParameterHandler& prm) {
  prm.declare_entry("scene", "cone-plate", dealii::Patterns::Selection(scenes().selection()),
                    "which geometry: the subsection of that name holds its parameters");
  for (const SceneEntry& scene : scenes().entries()) scene.declare(prm);
}

std::unique_ptr<Scene> make_scene(ParameterHandler& prm, const Material& material,
                                  const fe::SolverSettings& settings,
                                  const std::filesystem::path& scene_directory) {
  return scenes().at(prm.get("scene")).make({prm, material, settings, scene_directory});
}

}  // namespace softglass::macro
