// Adaptive refinement with the solution carried over, shared by the scalar
// and the Stokes solvers: the cells already flagged are refined (or
// coarsened), `setup_system` renumbers the degrees of freedom and rebuilds the
// constraints and sparsity on the new mesh, and the old solution is
// interpolated onto it. The caller then re-imposes its boundary values.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/solution_transfer.h>

namespace softglass::macro::fe {

template <int dim, class SetupSystem>
void refine_and_transfer(dealii::Triangulation<dim>& triangulation,
                         const dealii::DoFHandler<dim>& dof_handler,
                         dealii::Vector<double>& solution, SetupSystem&& setup_system) {
  dealii::SolutionTransfer<dim> transfer(dof_handler);
  triangulation.prepare_coarsening_and_refinement();
  transfer.prepare_for_coarsening_and_refinement(solution);
  triangulation.execute_coarsening_and_refinement();
  setup_system();
  dealii::Vector<double> interpolated(dof_handler.n_dofs());
  transfer.interpolate(solution, interpolated);
  solution = interpolated;
}

}  // namespace softglass::macro::fe
