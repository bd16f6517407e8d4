// The finite-element solver of the reduced scalar problem (scalar_problem.h),
// in the manner of the deal.II tutorials: one class, setup_system / assemble /
// solve / refine_mesh / output_results / run, instantiated for 1D sections
// (channel, pipe, Couette without end effects) and 2D ones (duct, meridian
// planes of Couette, cone–plate and plates).
//
// One call of run() computes one operating point (one pressure gradient or one
// rotation rate) with the chosen method and reports the outputs every scene
// needs — c∫ρu (the flow rate), c∫ρ τγ̇ (the dissipation: torque × Ω, or
// flow rate × G), the yielded fraction, a boundary integral of a function of
// the shear rate (normal forces) — together with its estimated discretisation
// and regularisation errors and its cost. A sweep calls run() repeatedly on the
// same solver, which starts each point from the previous point's solution.
#pragma once

#include <deal.II/grid/tria.h>

#include <filesystem>
#include <functional>
#include <memory>

#include "macro/fe/scalar_problem.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/shear_law.h"

namespace softglass::macro::fe {

/// The integrals one solution yields.
struct Outputs {
  double flow = 0.0;              ///< c ∫ ρ u dx
  /// c ∫ ρ τ(γ̇) γ̇ dx + c ∫_Γs ρ σ_w V_s ds: bulk and wall dissipation
  double dissipation = 0.0;
  double yielded_fraction = 0.0;  ///< ∫_{|τ|>τ_y} ρ dx / ∫ ρ dx
  double boundary = 0.0;          ///< c ∫_Γ g(γ̇) ρ ds on the requested boundary
  double max_value = 0.0;         ///< max |u| at the nodes
};

struct PointResult {
  Outputs value;
  /// |value − value on the mesh before the last refinement cycle|, per output.
  Outputs discretisation_error;
  /// |value − value at 10ε| / 9 (the O(ε) law); ALG2: the outputs' change
  /// over the last tenth of its iterations.
  Outputs regularisation_error;
  unsigned cells = 0, dofs = 0;
  unsigned iterations = 0;  ///< Newton (or ALG2) iterations, all cycles
  double wall_time = 0.0;   ///< [s]
};

/// What a scene asks of the boundary output: c ∫_Γ g(γ̇) ρ ds on boundary `id`.
struct BoundaryFunctional {
  dealii::types::boundary_id id = dealii::numbers::invalid_boundary_id;
  std::function<double(double rate)> integrand;
};

template <int dim>
class ScalarFlowSolver {
 public:
  /// `base_mesh` is copied; every operating point starts from it (refined
  /// settings.global_refinements times) and adapts its own copy. Walls in
  /// `slip` take the Robin condition of their slip law (scalar_problem.h);
  /// InputError if any does and the method is the augmented Lagrangian, which
  /// has no slip walls.
  ScalarFlowSolver(const dealii::Triangulation<dim>& base_mesh, unsigned mapping_degree,
                   const SectionWeights& weights, std::shared_ptr<const ShearLaw> law,
                   const WallSlip& slip, const SolverSettings& settings);
  ~ScalarFlowSolver();

  /// Solves one operating point; NumericalError if a solve does not converge.
  PointResult run(const Drive& drive, const BoundaryFunctional& boundary = {});

  /// Writes u, γ̇, |τ|, η and the yielded mask of the last point (VTU).
  void output_results(const std::filesystem::path& file) const;

 private:
  class Implementation;
  std::unique_ptr<Implementation> impl_;
};

}  // namespace softglass::macro::fe
