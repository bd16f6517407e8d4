// Duct of any section: the Mosolov problem −∇·(η(|∇w|)∇w) = G on the section,
// w = 0 on the wall (macro.md). The section is a rectangle, a circle (whose
// closed form, the pipe's, is reported beside the result) or a Gmsh mesh; every
// boundary of a Gmsh mesh is wall.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <fmt/format.h>

#include <numbers>

#include "common/errors.h"
#include "macro/exact/pipe.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/reduced_scene.h"

namespace softglass::macro {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

void declare_duct(ParameterHandler& prm) {
  prm.enter_subsection("duct");
  prm.declare_entry("section", "rectangle", Patterns::Selection("rectangle|circle|gmsh"),
                    "rectangle | circle | gmsh");
  prm.declare_entry("width", "0.01", Patterns::Double(), "rectangle: width [m], > 0");
  prm.declare_entry("height", "0.01", Patterns::Double(), "rectangle: height [m], > 0");
  prm.declare_entry("radius", "0.005", Patterns::Double(), "circle: radius [m], > 0");
  prm.declare_entry(
      "mesh file", "", Patterns::Anything(),
      "gmsh: a 2D quadrilateral .msh file, lengths in m (relative to the scene file)");
  prm.declare_entry("cells", "8", Patterns::Integer(1, 1000),
                    "rectangle: cells along the longer side");
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_duct(ParameterHandler& prm, const Material& material,
                                 const fe::SolverSettings& settings,
                                 const std::filesystem::path& scene_directory) {
  prm.enter_subsection("duct");
  const std::string section = prm.get("section");
  dealii::Triangulation<2> mesh;
  ReducedSceneSpec<2> spec;
  const std::shared_ptr<const ShearLaw> law = material.shear;
  if (section == "rectangle") {
    const double a = entries::positive(prm, "duct", "width", "m");
    const double b = entries::positive(prm, "duct", "height", "m");
    const unsigned n = prm.get_integer("cells");
    const unsigned na = std::max(1u, unsigned(std::lround(n * a / std::max(a, b))));
    const unsigned nb = std::max(1u, unsigned(std::lround(n * b / std::max(a, b))));
    meshes::rectangle(mesh, -0.5 * a, 0.5 * a, -0.5 * b, 0.5 * b, na, nb);
    spec.description = fmt::format("duct, rectangular section {} m x {} m (Mosolov problem)", a, b);
  } else if (section == "circle") {
    const double R = entries::positive(prm, "duct", "radius", "m");
    meshes::disc(mesh, R);
    spec.mapping_degree = 2;
    spec.description = fmt::format("duct, circular section of radius {} m (Mosolov problem)", R);
    spec.reference = [law, R](double G) {
      return exact::flow_rate(*law, exact::Pipe{.radius = R, .pressure_gradient = G});
    };
  } else {
    std::filesystem::path file = prm.get("mesh file");
    require(!file.empty(),
            "duct: mesh file = '' is not allowed with section = gmsh; allowed: a .msh file");
    if (file.is_relative()) file = scene_directory / file;
    meshes::gmsh(mesh, file);
    spec.description = fmt::format("duct, section from {} (Mosolov problem)", file.string());
  }
  prm.leave_subsection();
  for (const auto& face : mesh.active_face_iterators())
    if (face->at_boundary()) face->set_boundary_id(0);

  // The mean wall stress G A/P sets the shear-rate scale.
  double perimeter = 0.0;
  for (const auto& face : mesh.active_face_iterators())
    if (face->at_boundary()) perimeter += face->measure();
  const double hydraulic = dealii::GridTools::volume(mesh) / perimeter;
  spec.weights = {.radial_weight = 0, .rate_radius_power = 0, .measure_factor = 1.0};
  spec.drive = [law, hydraulic](double G) {
    return fe::Drive{.source = G,
                     .boundary_values = {{0, 0.0}},
                     .characteristic_rate = pressure_rate_scale(*law, G * hydraulic)};
  };
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

SceneEntry duct_scene() {
  return {
      {"duct",
       "pressure-driven flow along a duct of any section",
       {},
       [](const SceneSpec& s) { return make_duct(s.prm, s.material, s.settings, s.directory); }},
      declare_duct};
}

}  // namespace softglass::macro
