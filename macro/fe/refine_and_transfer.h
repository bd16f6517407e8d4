// Adaptive refinement with the solution carried over, shared by the scalar
// and the Stokes solvers: the cells already flagged are refined (or
// coarsened), `setup_system` renumbers the degrees of freedom, rebuilds the
// constraints and sparsity on the new mesh and returns a vector laid out for
// them, and the old solution is interpolated into it. The caller then
// re-imposes its boundary values.
//
// Two overloads, chosen by the mesh's type: a serial triangulation, where the
// old solution is read wherever it is needed, and a distributed one, where
// each rank sends the values of its cells to whichever rank owns their
// children after repartitioning — the transfer then needs the old solution
// with ghost values (`readable`) and writes a vector without them.
#pragma once

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/solution_transfer.h>

#include <utility>

namespace softglass::macro::fe {

template <int dim, class VectorType, class SetupSystem>
void refine_and_transfer(dealii::Triangulation<dim>& triangulation,
                         const dealii::DoFHandler<dim>& dof_handler, const VectorType& readable,
                         VectorType& solution, SetupSystem&& setup_system) {
  dealii::SolutionTransfer<dim, VectorType> transfer(dof_handler);
  triangulation.prepare_coarsening_and_refinement();
  transfer.prepare_for_coarsening_and_refinement(readable);
  triangulation.execute_coarsening_and_refinement();
  VectorType interpolated = setup_system();
  transfer.interpolate(readable, interpolated);
  solution = std::move(interpolated);
}

template <int dim, class VectorType, class SetupSystem>
void refine_and_transfer(dealii::parallel::distributed::Triangulation<dim>& triangulation,
                         const dealii::DoFHandler<dim>& dof_handler, const VectorType& readable,
                         VectorType& solution, SetupSystem&& setup_system) {
  dealii::parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dof_handler);
  triangulation.prepare_coarsening_and_refinement();
  transfer.prepare_for_coarsening_and_refinement(readable);
  triangulation.execute_coarsening_and_refinement();
  VectorType interpolated = setup_system();
  transfer.interpolate(interpolated);
  solution = std::move(interpolated);
}

}  // namespace softglass::macro::fe
