#include "macro/fe/direct_solver.h"

#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

#include <string>

#include "common/errors.h"

namespace softglass::macro::fe {

namespace {

// MUMPS's control parameters (ICNTL, Fortran numbering).
constexpr int kOrdering = 7;    // fill-reducing ordering of a sequential analysis:
constexpr int kMetis = 5;       //   METIS nested dissection
constexpr int kPrintLevel = 4;  // 0: no messages

// (No fmt here: Trilinos' Teuchos headers make fmt's unqualified calls ambiguous.)
void check(int status, const char* step) {
  if (status != 0)
    throw NumericalError("sparse direct solver (MUMPS): " + std::string(step) +
                         " failed (Amesos status " + std::to_string(status) + ")");
}

}  // namespace

DirectSolver::DirectSolver(MatrixKind kind) : kind_(kind) {}
DirectSolver::~DirectSolver() = default;

void DirectSolver::clear() {
  solver_.reset();
  problem_.reset();
}

void DirectSolver::analyse(const dealii::TrilinosWrappers::SparseMatrix& matrix) {
  clear();
  problem_ = std::make_unique<Epetra_LinearProblem>();
  // Amesos reads the matrix through a non-const pointer but does not modify it.
  problem_->SetOperator(const_cast<Epetra_CrsMatrix*>(&matrix.trilinos_matrix()));
  auto mumps = std::make_unique<Amesos_Mumps>(*problem_);
  Teuchos::ParameterList parameters;
  parameters.set("MatrixProperty", kind_ == MatrixKind::positive_definite ? "SPD" : "symmetric");
  check(mumps->SetParameters(parameters), "setting its parameters");
  mumps->SetICNTL(kOrdering, kMetis);
  mumps->SetICNTL(kPrintLevel, 0);
  solver_ = std::move(mumps);
  check(solver_->SymbolicFactorization(), "the symbolic analysis");
}

void DirectSolver::factorise() {
  check(solver_->NumericFactorization(), "the factorisation");
}

void DirectSolver::solve(dealii::TrilinosWrappers::MPI::Vector& x,
                         const dealii::TrilinosWrappers::MPI::Vector& b) {
  problem_->SetLHS(&x.trilinos_vector());
  problem_->SetRHS(const_cast<Epetra_MultiVector*>(&b.trilinos_vector()));
  check(solver_->Solve(), "the solve");
}

}  // namespace softglass::macro::fe
