#include "macro/scenes/scene.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/errors.h"

namespace softglass::macro {

using dealii::ParameterHandler;

// Each scene lives in its own file.
void declare_channel_and_pipe(ParameterHandler&);
void declare_duct(ParameterHandler&);
void declare_couette(ParameterHandler&);
void declare_cone_plate(ParameterHandler&);
void declare_parallel_plates(ParameterHandler&);
void declare_stokes_scenes(ParameterHandler&);
std::unique_ptr<Scene> make_channel(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_pipe(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_duct(ParameterHandler&, const Material&, const fe::SolverSettings&,
                                 const std::filesystem::path&);
std::unique_ptr<Scene> make_couette(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_cone_plate(ParameterHandler&, const Material&,
                                       const fe::SolverSettings&);
std::unique_ptr<Scene> make_parallel_plates(ParameterHandler&, const Material&,
                                            const fe::SolverSettings&);
std::unique_ptr<Scene> make_cavity(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_obstacle(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_cylinder(ParameterHandler&, const Material&, const fe::SolverSettings&);
std::unique_ptr<Scene> make_contraction(ParameterHandler&, const Material&,
                                        const fe::SolverSettings&);

std::vector<std::string> scene_names() {
  return {"channel",         "pipe",   "duct",     "couette",     "cone-plate",
          "parallel-plates", "cavity", "obstacle", "contraction", "cylinder"};
}

void declare_scenes(ParameterHandler& prm) {
  prm.declare_entry("scene", "cone-plate",
                    dealii::Patterns::Selection(fmt::format("{}", fmt::join(scene_names(), "|"))),
                    "which geometry: the subsection of that name holds its parameters");
  declare_channel_and_pipe(prm);
  declare_duct(prm);
  declare_couette(prm);
  declare_cone_plate(prm);
  declare_parallel_plates(prm);
  declare_stokes_scenes(prm);
}

std::unique_ptr<Scene> make_scene(ParameterHandler& prm, const Material& material,
                                  const fe::SolverSettings& settings,
                                  const std::filesystem::path& scene_directory) {
  const std::string name = prm.get("scene");
  if (name == "channel") return make_channel(prm, material, settings);
  if (name == "pipe") return make_pipe(prm, material, settings);
  if (name == "duct") return make_duct(prm, material, settings, scene_directory);
  if (name == "couette") return make_couette(prm, material, settings);
  if (name == "cone-plate") return make_cone_plate(prm, material, settings);
  if (name == "parallel-plates") return make_parallel_plates(prm, material, settings);
  if (name == "cavity") return make_cavity(prm, material, settings);
  if (name == "obstacle") return make_obstacle(prm, material, settings);
  if (name == "cylinder") return make_cylinder(prm, material, settings);
  if (name == "contraction") return make_contraction(prm, material, settings);
  throw InputError(
      fmt::format("scene = '{}' is unknown; allowed: {}", name, fmt::join(scene_names(), ", ")));
}

}  // namespace softglass::macro
