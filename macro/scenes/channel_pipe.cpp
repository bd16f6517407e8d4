// Plane channel and pipe: 1D sections (macro.md: u_x(y); u_z(r)).
//
// channel: half the channel, 0 ≤ y ≤ H, symmetry at y = 0 (natural condition),
//          no slip at y = H; ρ = 1, flow rate per unit width Q = 2∫₀^H u dy.
// pipe:    0 ≤ r ≤ R, ρ = r (the axis needs no condition), no slip at r = R;
//          Q = 2π∫₀^R u r dr.
// Both are driven by G = −dp/dx. The closed forms of exact/channel.h and
// exact/pipe.h are reported beside the finite-element values. `slip walls =
// walls` (channel: both, the half channel's symmetry) or `wall` (pipe) makes
// the walls slip by the law of `subsection slip`, and the closed forms with
// them.
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <numbers>

#include "macro/exact/channel.h"
#include "macro/exact/pipe.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/reduced_scene.h"
#include "macro/scenes/slip_walls.h"

namespace softglass::macro {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// The wall at y = H or r = R (id 1 of meshes::interval).
const std::vector<Wall> kChannelWalls{{"walls", 1}};
const std::vector<Wall> kPipeWall{{"wall", 1}};

}  // namespace

void declare_channel(ParameterHandler& prm) {
  prm.enter_subsection("channel");
  prm.declare_entry("half height", "0.005", Patterns::Double(), "H [m], > 0: walls at y = +-H");
  prm.declare_entry("cells", "8", Patterns::Integer(1, 10000), "cells across the half channel");
  declare_slip_walls(prm, kChannelWalls);
  prm.leave_subsection();
}

void declare_pipe(ParameterHandler& prm) {
  prm.enter_subsection("pipe");
  prm.declare_entry("radius", "0.005", Patterns::Double(), "R [m], > 0");
  prm.declare_entry("cells", "8", Patterns::Integer(1, 10000), "cells along the radius");
  declare_slip_walls(prm, kPipeWall);
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_channel(ParameterHandler& prm, const Material& material,
                                    const fe::SolverSettings& settings) {
  prm.enter_subsection("channel");
  const double H = entries::positive(prm, "channel", "half height", "m");
  const unsigned cells = prm.get_integer("cells");
  prm.leave_subsection();
  const fe::WallSlip slip = read_slip_walls(prm, "channel", kChannelWalls, H);
  dealii::Triangulation<1> mesh;
  meshes::interval(mesh, 0.0, H, cells);
  const std::shared_ptr<const ShearLaw> law = material.shear;
  ReducedSceneSpec<1> spec;
  spec.description = fmt::format(
      "plane channel, half height {} m: u_x(y) on [0, H], symmetry at y = 0, "
      "{} at y = H{}",
      H, slip.any() ? "slip" : "no slip", slip_description(slip, kChannelWalls));
  spec.weights = {.radial_weight = 0, .rate_radius_power = 0, .measure_factor = 2.0};
  spec.flow_unit = "m^2/s";
  spec.drive = [law, H](double G) {
    return fe::Drive{.source = G,
                     .boundary_values = {{1, 0.0}},
                     .characteristic_rate = pressure_rate_scale(*law, G * H)};
  };
  spec.reference = [law, H, slip](double G) {
    return exact::flow_rate(*law, exact::PlaneChannel{.half_height = H, .pressure_gradient = G},
                            slip.law.get());
  };
  spec.slip = slip;
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

std::unique_ptr<Scene> make_pipe(ParameterHandler& prm, const Material& material,
                                 const fe::SolverSettings& settings) {
  prm.enter_subsection("pipe");
  const double R = entries::positive(prm, "pipe", "radius", "m");
  const unsigned cells = prm.get_integer("cells");
  prm.leave_subsection();
  const fe::WallSlip slip = read_slip_walls(prm, "pipe", kPipeWall, R);
  dealii::Triangulation<1> mesh;
  meshes::interval(mesh, 0.0, R, cells);
  const std::shared_ptr<const ShearLaw> law = material.shear;
  ReducedSceneSpec<1> spec;
  spec.description =
      fmt::format("pipe, radius {} m: u_z(r) on [0, R] (axisymmetric), {} at r = R{}", R,
                  slip.any() ? "slip" : "no slip", slip_description(slip, kPipeWall));
  spec.weights = {
      .radial_weight = 1, .rate_radius_power = 0, .measure_factor = 2.0 * std::numbers::pi};
  spec.drive = [law, R](double G) {
    return fe::Drive{.source = G,
                     .boundary_values = {{1, 0.0}},
                     .characteristic_rate = pressure_rate_scale(*law, 0.5 * G * R)};
  };
  spec.reference = [law, R, slip](double G) {
    return exact::flow_rate(*law, exact::Pipe{.radius = R, .pressure_gradient = G},
                            slip.law.get());
  };
  spec.slip = slip;
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

SceneEntry channel_scene() {
  return {{"channel",
           "pressure-driven flow between two plane walls",
           {},
           [](const SceneSpec& s) { return make_channel(s.prm, s.material, s.settings); }},
          declare_channel};
}

SceneEntry pipe_scene() {
  return {{"pipe",
           "pressure-driven flow along a circular pipe",
           {},
           [](const SceneSpec& s) { return make_pipe(s.prm, s.material, s.settings); }},
          declare_pipe};
}

}  // namespace softglass::macro
