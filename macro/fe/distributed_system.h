// The linear algebra of one finite-element mesh distributed over the ranks of
// a communicator, shared by the scalar and the Stokes solvers: the degrees of
// freedom this rank owns and those it sees (its cells' and its ghost cells'),
// the system matrix with its sparse direct factorisation, the residual, and a
// copy of a vector with the seen entries, for evaluating fields on the cells.
//
// Use: after distribute_dofs(), set_dofs(); make the constraints on `relevant`;
// then make_matrix(), which returns a zero vector of owned entries.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include "macro/fe/direct_solver.h"

namespace softglass::macro::fe {

using VectorType = dealii::TrilinosWrappers::MPI::Vector;

/// The cells this rank assembles and integrates over.
template <int dim>
auto owned_cells(const dealii::DoFHandler<dim>& dof_handler) {
  return dof_handler.active_cell_iterators() | dealii::IteratorFilters::LocallyOwnedCell();
}

class DistributedSystem {
 public:
  DistributedSystem(MPI_Comm communicator, MatrixKind kind)
      : communicator_(communicator), direct_(kind) {}

  template <int dim>
  void set_dofs(const dealii::DoFHandler<dim>& dof_handler) {
    direct_.clear();  // before the matrix it analysed is replaced
    owned = dof_handler.locally_owned_dofs();
    dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
  }

  /// The matrix's sparsity (condensed with `constraints`), its ordering and
  /// symbolic factorisation, the residual; a zero vector of owned entries.
  template <int dim>
  VectorType make_matrix(const dealii::DoFHandler<dim>& dof_handler,
                         const dealii::AffineConstraints<double>& constraints) {
    dealii::DynamicSparsityPattern dsp(relevant);
    dealii::DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    dealii::SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator_, relevant);
    matrix.reinit(owned, owned, dsp, communicator_);
    direct_.analyse(matrix);
    residual.reinit(owned, communicator_);
    ghosted_.reinit(owned, relevant, communicator_);
    return vector();
  }

  /// A zero vector of owned entries.
  VectorType vector() const { return VectorType(owned, communicator_); }
  /// `owned_vector` with the entries of the ghost cells' dofs as well.
  const VectorType& readable(const VectorType& owned_vector) const {
    ghosted_ = owned_vector;
    return ghosted_;
  }
  /// Factorises the matrix's current values; x = A⁻¹ b with the last factorisation.
  void factorise() { direct_.factorise(); }
  void solve(VectorType& x, const VectorType& b) { direct_.solve(x, b); }

  dealii::IndexSet owned, relevant;
  dealii::TrilinosWrappers::SparseMatrix matrix;
  VectorType residual;

 private:
  MPI_Comm communicator_;
  DirectSolver direct_;  // declared after the matrix: destroyed before it
  mutable VectorType ghosted_;
};

}  // namespace softglass::macro::fe
