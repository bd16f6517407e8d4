// Parallel plates: the upper plate (radius R) turns at Ω a gap h above the
// fixed lower one, rim free; ω(r, z) in the meridian plane. Without inertia
// the flow is the torsional one, ω = Ω z/h exactly, and the torque is the
// closed form of exact/parallel_plates.h, reported beside the result. Slip
// (`slip walls = upper plate, lower plate`, either or both) by the law of
// `subsection slip`: the closed form stays the no-slip one, so the deviation
// from it is then the slip's effect on the torque.
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <numbers>

#include "macro/exact/parallel_plates.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/reduced_scene.h"
#include "macro/scenes/slip_walls.h"

namespace softglass::macro {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// The turning plate on top (id 3), the fixed one below (id 2): meshes::rectangle.
const std::vector<Wall> kWalls{{"upper plate", 3}, {"lower plate", 2}};

}  // namespace

void declare_parallel_plates(ParameterHandler& prm) {
  prm.enter_subsection("parallel-plates");
  prm.declare_entry("radius", "0.025", Patterns::Double(), "R [m], > 0");
  prm.declare_entry("gap", "0.001", Patterns::Double(), "h [m], > 0");
  prm.declare_entry("radial cells", "16", Patterns::Integer(1, 10000), "cells along the radius");
  prm.declare_entry("gap cells", "2", Patterns::Integer(1, 1000), "cells across the gap");
  declare_slip_walls(prm, kWalls);
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_parallel_plates(ParameterHandler& prm, const Material& material,
                                            const fe::SolverSettings& settings) {
  prm.enter_subsection("parallel-plates");
  const double R = entries::positive(prm, "parallel-plates", "radius", "m");
  const double h = entries::positive(prm, "parallel-plates", "gap", "m");
  const unsigned radial = prm.get_integer("radial cells"), gap = prm.get_integer("gap cells");
  prm.leave_subsection();
  const fe::WallSlip slip = read_slip_walls(prm, "parallel-plates", kWalls, h);
  dealii::Triangulation<2> mesh;
  meshes::rectangle(mesh, 0.0, R, 0.0, h, radial, gap);
  const std::shared_ptr<const ShearLaw> law = material.shear;
  const exact::ParallelPlates plates{.radius = R, .gap = h};
  ReducedSceneSpec<2> spec;
  spec.description = fmt::format(
      "parallel plates R = {} m, gap {} m: omega(r, z) in the meridian plane, upper plate at "
      "Omega{}",
      R, h, slip_description(slip, kWalls));
  spec.kind = DriveKind::rotation;
  spec.weights = {
      .radial_weight = 1, .rate_radius_power = 1, .measure_factor = 2.0 * std::numbers::pi};
  spec.drive = [R, h](double omega) {
    return fe::Drive{.source = 0.0,
                     .boundary_values = {{3, omega}, {2, 0.0}},
                     .characteristic_rate = omega * R / h};
  };
  spec.reference = [law, plates](double omega) { return exact::torque(*law, plates, omega); };
  spec.slip = slip;
  // F = π ∫ (N1 − N2)(γ̇) r dr (exact/parallel_plates.h): ½(N1 − N2) over the plate.
  const auto n1 = material.first_normal_stress_difference;
  const auto n2 = material.second_normal_stress_difference;
  if (!n1->vanishes() || !n2->vanishes()) {
    spec.normal_force = {.id = 2, .integrand = [n1, n2](double rate) {
                           return 0.5 * (n1->value(rate) - n2->value(rate));
                         }};
  }
  // The rim rate ΩR/h and the Newtonian (apparent) rim stress 2M/(πR³).
  spec.instrument = InstrumentConstants{
      .strain_constant = R / h,
      .stress_constant = 2.0 / (std::numbers::pi * R * R * R),
      .convention = "plates: rim rate Omega R/h, apparent rim stress 2M/(pi R^3)"};
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

SceneEntry parallel_plates_scene() {
  return {{"parallel-plates",
           "parallel plates: the upper plate turns above the fixed one",
           {},
           [](const SceneSpec& s) { return make_parallel_plates(s.prm, s.material, s.settings); }},
          declare_parallel_plates};
}

}  // namespace softglass::macro
