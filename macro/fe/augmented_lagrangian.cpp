// ALG2 (augmented_lagrangian.h), instantiated for the scalar solver's 1D and
// 2D sections.
#include "macro/fe/augmented_lagrangian.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "common/errors.h"

namespace softglass::macro::fe {

using namespace dealii;

template <int dim>
AugmentedLagrangian<dim>::AugmentedLagrangian(const SectionDiscretisation<dim>& section,
                                              DistributedSystem& system,
                                              const AffineConstraints<double>& constraints,
                                              const ShearLaw& law, const SolverSettings& settings)
    : section_(section),
      system_(system),
      constraints_(constraints),
      law_(law),
      settings_(settings) {}

template <int dim>
unsigned AugmentedLagrangian<dim>::solve(VectorType& u, const Drive& drive,
                                         const RegularisedLaw* start_law,
                                         const std::function<void()>& record) {
  // ALG2's penalty: the viscosity scale η(γ̇_c) of the scene.
  penalty_ = settings_.al_relative_penalty * law_.viscosity(drive.characteristic_rate);
  // The quadrature of every integral over the section (as in the scalar
  // solver), fresh for the new mesh.
  fe_values_.emplace(
      section_.mapping, section_.fe, QGauss<dim>(section_.fe.degree + 1),
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  FEValues<dim>& fe_values = *fe_values_;
  const auto cells = owned_cells(section_.dof_handler);
  const std::size_t points =
      std::distance(cells.begin(), cells.end()) * fe_values.n_quadrature_points;
  rate_.assign(points, Tensor<1, dim>());
  multiplier_.assign(points, Tensor<1, dim>());
  rate_norm_.assign(points, 0.0);

  // Start from the current u (a regularised solution, when there is one):
  // γ = s∇u and λ = its regularised stress, so ALG2 only corrects the plug.
  const VectorType& field = system_.readable(u);
  std::vector<Tensor<1, dim>> gradients(fe_values.n_quadrature_points);
  std::size_t k = 0;
  for (const auto& cell : cells) {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(field, gradients);
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      rate_[k] = section_.weights.s(fe_values.quadrature_point(q)[0]) * gradients[q];
      if (start_law) multiplier_[k] = start_law->viscosity(rate_[k].norm()).value * rate_[k];
      ++k;
    }
  }

  VectorType rhs = system_.vector();
  assemble_u_step(drive, true, rhs);
  system_.factorise();
  unsigned iteration = 0, next_record = 1;
  for (iteration = 1; iteration <= settings_.al_max_iterations; ++iteration) {
    if (iteration > 1) assemble_u_step(drive, false, rhs);
    system_.solve(u, rhs);
    constraints_.distribute(u);
    if (local_steps(u, drive) <= settings_.al_tolerance) break;
    if (record && iteration >= next_record) {
      record();
      recorded_iteration_ = iteration;
      next_record = iteration + std::max(1u, iteration / 10);
    }
  }
  iterations_ = iteration;
  if (iteration > settings_.al_max_iterations) {
    throw NumericalError(fmt::format("augmented Lagrangian did not reach {} in {} iterations",
                                     settings_.al_tolerance, settings_.al_max_iterations));
  }
  return iteration;
}

// Step 1's system. Its matrix r∫ρs²∇φ_i·∇φ_j is the same at every iteration
// and is assembled once; the Dirichlet data enter the right-hand side through
// the inhomogeneous constraints, so the local matrices are needed every time.
template <int dim>
void AugmentedLagrangian<dim>::assemble_u_step(const Drive& drive, bool with_matrix,
                                               VectorType& rhs) {
  FEValues<dim>& fe_values = *fe_values_;
  const unsigned n = section_.fe.n_dofs_per_cell(), nq = fe_values.n_quadrature_points;
  std::vector<types::global_dof_index> dofs(n);
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  rhs = 0.0;
  if (with_matrix) system_.matrix = 0.0;
  std::size_t k = 0;
  for (const auto& cell : owned_cells(section_.dof_handler)) {
    fe_values.reinit(cell);
    cell_matrix = 0.0;
    cell_rhs = 0.0;
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const double r = fe_values.quadrature_point(q)[0];
      const double sq = section_.weights.s(r), jxw = section_.weights.rho(r) * fe_values.JxW(q);
      const Tensor<1, dim> load = sq * (multiplier_[k + q] - penalty_ * rate_[k + q]);
      for (unsigned i = 0; i < n; ++i) {
        cell_rhs(i) +=
            (drive.source * fe_values.shape_value(i, q) - load * fe_values.shape_grad(i, q)) * jxw;
        for (unsigned j = 0; j < n; ++j)
          cell_matrix(i, j) +=
              penalty_ * sq * sq * (fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q)) * jxw;
      }
    }
    cell->get_dof_indices(dofs);
    if (with_matrix) {
      constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, system_.matrix, rhs);
    } else {
      constraints_.distribute_local_to_global(cell_rhs, dofs, rhs, cell_matrix);
    }
    k += nq;
  }
  if (with_matrix) system_.matrix.compress(VectorOperation::add);
  rhs.compress(VectorOperation::add);
}

template <int dim>
double AugmentedLagrangian<dim>::local_steps(const VectorType& u, const Drive& drive) {
  FEValues<dim>& fe_values = *fe_values_;
  std::vector<Tensor<1, dim>> gradients(fe_values.n_quadrature_points);
  const VectorType& field = system_.readable(u);
  double mismatch = 0.0, norm = 0.0, volume = 0.0;
  std::size_t k = 0;
  for (const auto& cell : owned_cells(section_.dof_handler)) {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(field, gradients);
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const double r = fe_values.quadrature_point(q)[0];
      const Tensor<1, dim> strain = section_.weights.s(r) * gradients[q];
      const Tensor<1, dim> chi = multiplier_[k] + penalty_ * strain;
      const double chi_norm = chi.norm();
      const double g = law_.proximal_rate(chi_norm, penalty_);
      rate_[k] = g > 0.0 ? (g / chi_norm) * chi : Tensor<1, dim>();
      rate_norm_[k] = g;
      multiplier_[k] += penalty_ * (strain - rate_[k]);
      const double w = section_.weights.rho(r) * fe_values.JxW(q);
      mismatch += (strain - rate_[k]).norm_square() * w;
      norm += rate_[k].norm_square() * w;
      volume += w;
      ++k;
    }
  }
  mismatch = Utilities::MPI::sum(mismatch, section_.communicator);
  norm = Utilities::MPI::sum(norm, section_.communicator);
  volume = Utilities::MPI::sum(volume, section_.communicator);
  // Relative to the rate field, or to the scene's rate scale where the
  // material barely flows (a plug filling the section has γ = 0).
  const double scale = drive.characteristic_rate * drive.characteristic_rate * volume;
  return std::sqrt(mismatch / std::max(norm, scale));
}

template <int dim>
double AugmentedLagrangian<dim>::error_divisor() const {
  return iterations_ > recorded_iteration_
             ? double(iterations_ - recorded_iteration_) / std::max(1u, recorded_iteration_)
             : 1.0;
}

template class AugmentedLagrangian<1>;
template class AugmentedLagrangian<2>;

}  // namespace softglass::macro::fe
