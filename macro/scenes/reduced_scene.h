// The scenes with a scalar reduced formulation (scalar_problem.h) share one
// implementation: a mesh, the section weights, how an operating point drives
// the problem, which boundary carries the normal force, and the closed-form
// value of the ideal geometry (if any) to report the deviation from.
#pragma once

#include <deal.II/grid/tria.h>

#include <functional>
#include <memory>
#include <string>

#include "macro/fe/scalar_flow_solver.h"
#include "macro/scenes/scene.h"

namespace softglass::macro {

enum class DriveKind { pressure, rotation };

template <int dim>
struct ReducedSceneSpec {
  std::string description;
  DriveKind kind = DriveKind::pressure;
  unsigned mapping_degree = 1;
  fe::SectionWeights weights;
  /// The problem at one operating point (G or Ω).
  std::function<fe::Drive(double)> drive;
  /// Rotation scenes: the plate's normal force as a boundary integral (empty:
  /// no normal-force column).
  fe::BoundaryFunctional normal_force;
  /// The closed form of the ideal geometry at one operating point (empty: none).
  std::function<double(double)> reference;
  /// Unit of the flow rate: m^2/s per unit width (channel) or m^3/s.
  std::string flow_unit = "m^3/s";
  /// Rotational rheometers: how the instrument reports Ω and M as γ̇ and τ.
  std::optional<InstrumentConstants> instrument;
  /// The walls that slip (scenes/slip_walls.h); none by default.
  fe::WallSlip slip;
};

/// Builds the scene; `mesh` is copied by the solver.
template <int dim>
std::unique_ptr<Scene> make_reduced_scene(const dealii::Triangulation<dim>& mesh,
                                          ReducedSceneSpec<dim> spec, std::shared_ptr<const ShearLaw> law,
                                          const fe::SolverSettings& settings);

/// The shear rate that sets ε in pressure-driven flow at characteristic wall
/// stress τ_c: the law's rate at τ_c, or (below the yield stress, where the
/// material may not flow at all) at τ_y + 0.1 τ_c.
double pressure_rate_scale(const ShearLaw& law, double wall_stress);

}  // namespace softglass::macro
