// The sparse direct solver of the scalar finite-element solver's distributed
// systems: MUMPS (a parallel multifrontal LU/LDLᵀ) through Trilinos' Amesos.
//
// Why not deal.II's TrilinosWrappers::SolverDirect: it orders and analyses the
// matrix at every factorisation. A Newton iteration changes the values of the
// matrix but never its pattern, so here the fill-reducing ordering (METIS) and
// the symbolic analysis are done once per mesh, and each Newton step pays only
// for the numeric factorisation — in symmetric mode (LDLᵀ), which halves it:
// the scalar problem's matrices are symmetric positive definite, the Stokes
// saddle-point matrices symmetric indefinite.
#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace softglass::macro::fe {

enum class MatrixKind { positive_definite, symmetric_indefinite };

class DirectSolver {
 public:
  explicit DirectSolver(MatrixKind kind);
  ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// Orders and analyses the pattern of `matrix` (of the solver's kind), which
  /// must stay alive, with this pattern, until clear().
  void analyse(const dealii::TrilinosWrappers::SparseMatrix& matrix);
  /// Forgets the matrix: call it before the matrix is reinitialised or destroyed
  /// (MUMPS's clean-up uses the matrix's communicator).
  void clear();
  /// Factorises the matrix's current values; NumericalError if MUMPS fails.
  void factorise();
  /// x = A⁻¹ b with the last factorisation.
  void solve(dealii::TrilinosWrappers::MPI::Vector& x,
             const dealii::TrilinosWrappers::MPI::Vector& b);

 private:
  MatrixKind kind_;
  std::unique_ptr<Epetra_LinearProblem> problem_;
  std::unique_ptr<Amesos_BaseSolver> solver_;
};

}  // namespace softglass::macro::fe
