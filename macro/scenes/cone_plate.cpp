// Cone and plate: the cone (radius R, angle β, tip truncated to a gap h_t)
// turns at Ω above the fixed plate; ω(r, z) in the meridian plane, rim free.
//
// The closed form of exact/cone_plate.h — any angle, no truncation, spherical
// rim, filled to the cone's radius — is reported beside the result, so the
// table says by how much the truncation, the rim's shape and the fill level
// change the torque.
//
// Fill level. An underfilled sample ends at r = fill·R under the cone (its
// free surface shaped like the rim); its torque is about fill³ of the full
// one. An overfilled sample is modelled as a collar of the rim's gap height
// R tan β, from R out to fill·R, resting on the plate with its top and side
// free; it is sheared only through the sample at the cone's edge (the
// cone's edge face is taken as not wetted), so it adds the drag of a ring of
// material dragged along at the rim — a lower bound of a real overfill,
// which also wets the edge face.
//
// Slip (`slip walls = cone, plate`, either or both) by the law of `subsection
// slip`. The closed form stays the no-slip one of the ideal cone, so the
// deviation from it then includes the slip's effect on the torque.
//
// Normal force. The plate carries F = ∫ (−σ_zz) dA. For the steady simple
// shear of the ideal cone (uniform rate) the radial momentum balance gives
// F = πR² N1/2 (exact/cone_plate.h). Here the local rate on the plate varies
// (truncation, rim), and F is taken as ∫ N1(γ̇)/2 dA with the plate's local
// rate: the same balance applied ring by ring, neglecting the radial gradient
// of the rate and N2 (both vanish for the ideal cone).
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "macro/exact/cone_plate.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/reduced_scene.h"
#include "macro/scenes/slip_walls.h"

namespace softglass::macro {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

// The cone with its truncation (id 3) and the plate (id 2): meshes.h.
const std::vector<Wall> kWalls{{"cone", 3}, {"plate", 2}};

}  // namespace

void declare_cone_plate(ParameterHandler& prm) {
  prm.enter_subsection("cone-plate");
  prm.declare_entry("radius", "0.025", Patterns::Double(), "R [m], > 0");
  prm.declare_entry("angle", "2", Patterns::Double(), "beta [deg], the cone angle, 0 < beta < 30");
  prm.declare_entry("truncation", "48e-6", Patterns::Double(),
                    "h_t [m], the gap at the axis (cone tip removed), >= 0 and < R tan(beta)/2");
  prm.declare_entry(
      "rim", "spherical", Patterns::Selection("spherical|cylindrical"),
      "spherical (about the cone's apex, the closed form's rim) | cylindrical (r = R)");
  prm.declare_entry(
      "fill", "1", Patterns::Double(),
      "the sample's radius over R, in (0.5, 1.2): 1 filled to the rim; < 1 underfilled "
      "(a cylindrical or spherical free surface under the cone); > 1 overfilled (a "
      "collar of the rim's height beyond the cone's edge, top and side free)");
  prm.declare_entry("radial cells", "24", Patterns::Integer(2, 10000), "cells along the radius");
  prm.declare_entry("gap cells", "2", Patterns::Integer(1, 1000), "cells across the gap");
  declare_slip_walls(prm, kWalls);
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_cone_plate(ParameterHandler& prm, const Material& material,
                                       const fe::SolverSettings& settings) {
  prm.enter_subsection("cone-plate");
  const double R = entries::positive(prm, "cone-plate", "radius", "m");
  const double beta =
      entries::between(prm, "cone-plate", "angle", "deg", 0.0, 30.0) * std::numbers::pi / 180.0;
  const double h_t = entries::non_negative(prm, "cone-plate", "truncation", "m");
  require(h_t < 0.5 * R * std::tan(beta),
          fmt::format(
              "cone-plate: truncation = {} [m] is not allowed; allowed: < R tan(beta)/2 = {} [m]",
              h_t, 0.5 * R * std::tan(beta)));
  require(h_t > 0.0,
          "cone-plate: truncation = 0 [m] is not allowed (the apex would be a degenerate "
          "cell); allowed: > 0 [m], e.g. 1e-6 R for an ideal cone");
  const bool spherical = prm.get("rim") == "spherical";
  const double fill = entries::between(prm, "cone-plate", "fill", "1", 0.5, 1.2);
  require(h_t < 0.5 * std::min(fill, 1.0) * R * std::tan(beta),
          fmt::format("cone-plate: fill = {} leaves the truncation (h_t = {} m) more than half the "
                      "gap at the sample's rim; allowed: fill > 2 h_t/(R tan(beta)) = {}",
                      fill, h_t, 2.0 * h_t / (R * std::tan(beta))));
  const unsigned radial = prm.get_integer("radial cells"), gap = prm.get_integer("gap cells");
  prm.leave_subsection();
  const fe::WallSlip slip = read_slip_walls(prm, "cone-plate", kWalls, R * std::tan(beta));

  dealii::Triangulation<2> mesh;
  meshes::cone_plate(mesh, R, beta, h_t, spherical, fill, radial, gap);
  const std::shared_ptr<const ShearLaw> law = material.shear;
  const auto n1 = material.first_normal_stress_difference;
  const exact::ConePlate cone{.radius = R, .angle = beta};
  ReducedSceneSpec<2> spec;
  const std::string sample =
      fill == 1.0  ? fmt::format("filled to a {} rim", spherical ? "spherical" : "cylindrical")
      : fill < 1.0 ? fmt::format("underfilled to {} R, {} free surface", fill,
                                 spherical ? "spherical" : "cylindrical")
                   : fmt::format("overfilled: a collar out to {} R beyond the cone's edge", fill);
  spec.description = fmt::format(
      "cone and plate R = {} m, beta = {} deg, truncation {} m, sample {}: omega(r, z) in the "
      "meridian plane, cone at Omega, plate fixed{}",
      R, beta * 180.0 / std::numbers::pi, h_t, sample, slip_description(slip, kWalls));
  spec.kind = DriveKind::rotation;
  spec.mapping_degree = spherical && fill <= 1.0 ? 2 : 1;  // curved cells at a spherical rim
  spec.weights = {
      .radial_weight = 1, .rate_radius_power = 1, .measure_factor = 2.0 * std::numbers::pi};
  spec.drive = [beta](double omega) {
    return fe::Drive{.source = 0.0,
                     .boundary_values = {{3, omega}, {2, 0.0}},
                     .characteristic_rate = omega / std::tan(beta)};
  };
  if (!n1->vanishes()) {
    spec.normal_force = {.id = 2,
                         .integrand = [n1](double rate) { return 0.5 * n1->value(rate); }};
  }
  spec.reference = [law, cone](double omega) { return exact::torque(*law, cone, omega); };
  spec.slip = slip;
  // The cone's uniform rate Ω/β and the stress 3M/(2πR³) of a small angle.
  spec.instrument =
      InstrumentConstants{.strain_constant = 1.0 / beta,
                          .stress_constant = 3.0 / (2.0 * std::numbers::pi * R * R * R),
                          .convention = "small-angle cone: rate Omega/beta, stress 3M/(2 pi R^3)"};
  return make_reduced_scene(mesh, std::move(spec), law, settings);
}

SceneEntry cone_plate_scene() {
  return {{"cone-plate",
           "cone and plate: the truncated cone turns above the fixed plate",
           {},
           [](const SceneSpec& s) { return make_cone_plate(s.prm, s.material, s.settings); }},
          declare_cone_plate};
}

}  // namespace softglass::macro
