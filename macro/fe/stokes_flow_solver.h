// Plane creeping flow of a regularised Herschel–Bulkley material where the
// flow really is two-directional (lid-driven cavity, channel with an obstacle):
// the Stokes problem with the velocity–pressure pair (u, p) on Taylor–Hood
// Q2–Q1 elements,
//
//     −∇·(2η_ε(γ̇) D(u)) + ∇p = 0,   ∇·u = 0,     γ̇ = √(2 D:D),
//
// solved by Newton's method with continuation in ε, as the scalar solver
// (scalar_flow_solver.h) does, and nested iteration: the continuation runs on
// the mesh one uniform refinement coarser; then the preset's adaptive cycles
// (Kelly indicator of the velocity plus the cells a yield surface crosses).
// The change over the last refinement is the discretisation error estimate.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "macro/fe/solver_settings.h"
#include "macro/material/shear_law.h"

namespace softglass::macro::fe {

/// Velocity boundary data: a function of the position per boundary id.
using VelocityBoundaryValues =
    std::map<dealii::types::boundary_id,
             std::function<dealii::Tensor<1, 2>(const dealii::Point<2>&)>>;

/// What one solve imposes and measures.
struct StokesDrive {
  /// Walls and inflow: the velocity.
  VelocityBoundaryValues velocity{};
  /// Outflow boundaries, each a straight line x = const: the transverse
  /// velocity vanishes and the normal traction −p + 2η ∂u/∂x is zero, which
  /// fully developed (Poiseuille) flow satisfies with p = 0 there. Ids in
  /// neither list are free (zero traction, which developed flow does not
  /// satisfy with the symmetric-gradient form: it has shear stress there).
  std::set<dealii::types::boundary_id> straight_outflow{};
  /// γ̇_c: sets the regularisation scale ε = ε_rel γ̇_c.
  double characteristic_rate = 1.0;
  /// Forces are integrated over this boundary, the mean pressure over the
  /// other (invalid id: none).
  dealii::types::boundary_id force_boundary = dealii::numbers::invalid_boundary_id;
  dealii::types::boundary_id pressure_boundary = dealii::numbers::invalid_boundary_id;
  /// The velocity is sampled here on every mesh (so that point values get
  /// error estimates).
  std::vector<dealii::Point<2>> probes{};
};

struct StokesOutputs {
  double dissipation = 0.0;       ///< ∫ τ:D dA (per unit depth) [W/m]
  double yielded_fraction = 0.0;  ///< area where |τ| > τ_y over the whole area
  /// Force of the fluid on the boundary `force_boundary`, per unit depth [N/m].
  dealii::Tensor<1, 2> force;
  /// Mean pressure on the boundary `pressure_boundary` [Pa].
  double mean_pressure = 0.0;
  /// The velocity at the run's probe points [m/s].
  std::vector<dealii::Tensor<1, 2>> probes;
};

struct StokesResult {
  /// Final mesh; the mesh before the last refinement; the first (coarsest)
  /// mesh at ε and at 10ε (the regularisation estimate is their difference / 9).
  StokesOutputs value, coarse, first_mesh, at_ten_epsilon;
  unsigned cells = 0, dofs = 0, iterations = 0;
  double wall_time = 0.0;
};

class StokesFlowSolver {
 public:
  StokesFlowSolver(const dealii::Triangulation<2>& base_mesh, std::shared_ptr<const ShearLaw> law,
                   const SolverSettings& settings);
  ~StokesFlowSolver();

  /// Solves one operating point (warm-started from the previous one).
  StokesResult run(const StokesDrive& drive);

  /// u at points of the domain (last solve, fine mesh).
  std::vector<dealii::Tensor<1, 2>> velocity_at(const std::vector<dealii::Point<2>>& points) const;

  /// VTU of the last solve: velocity, pressure, γ̇, |τ|, yielded.
  void output_results(const std::filesystem::path& file) const;

 private:
  class Implementation;
  std::unique_ptr<Implementation> impl_;
};

}  // namespace softglass::macro::fe
