// Couette cell: the bob (radius R1, wetted length L) turns at Ω inside the
// fixed cup (radius R2). The unknown is the angular velocity ω (scalar_problem.h).
//
// end effects = false: ω(r) on [R1, R2], the infinitely long cell of macro.md,
//                      whose closed form (exact/couette.h) the solver must match.
// end effects = true:  ω(r, z) in the meridian plane, with the cup's bottom a
//                      distance h_b below the bob's base and a free surface
//                      level with the bob's top; the torque's deviation from the
//                      ideal cell is the end effect.
//
// Slip (`slip walls = bob, cup`, either or both): the bob (with its base) and
// the cup (with its bottom) slide by the law of `subsection slip`; the closed
// form of the ideal cell then has the same slip (exact/couette.h).
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <numbers>

#include "common/errors.h"
#include "macro/exact/couette.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/reduced_scene.h"
#include "macro/scenes/slip_walls.h"

namespace softglass::macro {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// The bob and its base (id 0), the cup and its bottom (id 1): meshes.h.
const std::vector<Wall> kWalls{{"bob", 0}, {"cup", 1}};

}  // namespace

void declare_couette(ParameterHandler& prm) {
  prm.enter_subsection("couette");
  prm.declare_entry("inner radius", "0.0125", Patterns::Double(), "R1 [m], the bob, > 0");
  prm.declare_entry("outer radius", "0.01356", Patterns::Double(), "R2 [m], the cup, > R1");
  prm.declare_entry("length", "0.0375", Patterns::Double(), "L [m], the bob's wetted length, > 0");
  prm.declare_entry("end effects", "false", Patterns::Bool(),
                    "true: the meridian plane with the cup's bottom; false: the infinite cell");
  prm.declare_entry("bottom gap", "0.0075", Patterns::Double(),
                    "h_b [m], bob base to cup bottom (end effects only), > 0");
  prm.declare_entry("gap cells", "8", Patterns::Integer(1, 1000), "cells across R2 - R1");
  declare_slip_walls(prm, kWalls);
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_couette(ParameterHandler& prm, const Material& material,
                                    const fe::SolverSettings& settings) {
  prm.enter_subsection("couette");
  const double R1 = entries::positive(prm, "couette", "inner radius", "m");
  const double R2 = entries::positive(prm, "couette", "outer radius", "m");
  require(R2 > R1, fmt::format("couette: outer radius = {} [m] is not allowed; allowed: > inner "
                               "radius = {} [m]",
                               R2, R1));
  const double L = entries::positive(prm, "couette", "length", "m");
  const bool ends = prm.get_bool("end effects");
  const double h_b = entries::positive(prm, "couette", "bottom gap", "m");
  const unsigned cells = prm.get_integer("gap cells");
  prm.leave_subsection();
  const fe::WallSlip slip = read_slip_walls(prm, "couette", kWalls, R2 - R1);

  const std::shared_ptr<const ShearLaw> law = material.shear;
  const exact::CouetteCell cell{.inner_radius = R1, .outer_radius = R2, .length = L};
  const auto slips = [&slip](dealii::types::boundary_id id) {
    return slip.walls.count(id) > 0 ? slip.law.get() : nullptr;
  };
  const exact::CouetteWalls walls{.inner = slips(0), .outer = slips(1)};
  // γ̇_c: the Newtonian rate at the bob, 2ΩR2²/(R2² − R1²).
  const double rate_factor = 2.0 * R2 * R2 / (R2 * R2 - R1 * R1);
  // The closed form holds the slip law by pointer; the lambda keeps it alive.
  const auto reference = [law, cell, walls, keep = slip.law](double omega) {
    return exact::torque(*law, cell, omega, walls);
  };
  // ISO 3219: the representative rate and stress of a narrow gap, at the
  // radius whose square is the mean of R1² and R2² (no end correction).
  const double r1s = R1 * R1, r2s = R2 * R2;
  const InstrumentConstants instrument{
      .strain_constant = (r1s + r2s) / (r2s - r1s),
      .stress_constant = (r1s + r2s) / (4.0 * std::numbers::pi * L * r1s * r2s),
      .convention = "ISO 3219 representative values of the gap, no end correction"};
  const auto drive = [rate_factor](double omega) {
    return fe::Drive{.source = 0.0,
                     .boundary_values = {{0, omega}, {1, 0.0}},
                     .characteristic_rate = rate_factor * omega};
  };
  if (!ends) {
    dealii::Triangulation<1> mesh;
    meshes::interval(mesh, R1, R2, cells);
    ReducedSceneSpec<1> spec;
    spec.description = fmt::format(
        "Couette cell R1 = {} m, R2 = {} m, L = {} m without end effects: omega(r), bob at Omega, "
        "cup fixed{}",
        R1, R2, L, slip_description(slip, kWalls));
    spec.kind = DriveKind::rotation;
    spec.weights = {
        .radial_weight = 1, .rate_radius_power = 1, .measure_factor = 2.0 * std::numbers::pi * L};
    spec.drive = drive;
    spec.reference = reference;
    spec.instrument = instrument;
    spec.slip = slip;
    return make_reduced_scene(mesh, std::move(spec), law, settings);
  }
  dealii::Triangulation<2> mesh;
  meshes::couette_with_bottom(mesh, R1, R2, L, h_b, cells);
  ReducedSceneSpec<2> spec;
  spec.description = fmt::format(
      "Couette cell R1 = {} m, R2 = {} m, L = {} m with its bottom (gap {} m) and free surface: "
      "omega(r, z) in the meridian plane{}",
      R1, R2, L, h_b, slip_description(slip, kWalls));
  spec.kind = DriveKind::rotation;
  spec.weights = {
      .radial_weight = 1, .rate_radius_power = 1, .measure_factor = 2.0 * std::numbers::pi};
  spec.drive = drive;
  spec.reference = reference;
  spec.instrument = instrument;
  spec.slip = slip;
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

SceneEntry couette_scene() {
  return {{"couette",
           "Couette cell: the bob turns inside the fixed cup",
           {},
           [](const SceneSpec& s) { return make_couette(s.prm, s.material, s.settings); }},
          declare_couette};
}

}  // namespace softglass::macro
