// The Taylor–Hood Stokes solver (stokes_flow_solver.h); the second heavy
// deal.II translation unit.
//
// Newton's method. With τ = 2η_ε(γ̇)D, N = √2 D/γ̇ and τ' = η + γ̇ dη/dγ̇,
//
//     ∂τ/∂D = 2[η 𝕀 + (τ' − η) N⊗N],   so   J(δu)(v) = ∫ 2η D(δu):D(v)
//             + 4 η'(γ̇)/γ̇ (D:D(δu))(D:D(v)) − ∫ δp ∇·v − ∫ q ∇·δu,
//
// a symmetric saddle-point matrix, factorised by MUMPS (direct_solver.h; the
// problems here have ≲ 10⁵ unknowns). Newton, its line search (the step halves
// until the residual decreases: there is no energy to minimise in (u, p)), the
// modified tangent after a short step and the continuation in ε are the
// policy of newton_continuation.h, shared with the scalar solver. When every
// boundary carries a velocity the pressure is fixed up to a constant: one
// pressure unknown is pinned to zero.
//
// Parallel, as the scalar solver: the mesh is distributed (p4est) over the
// ranks of settings.mesh_communicator, the matrix and vectors are Trilinos',
// integrals are summed over the ranks and every decision is taken on global
// quantities.
#include "macro/fe/stokes_flow_solver.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>
#include <deal.II/numerics/vector_tools_evaluate.h>
#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/errors.h"
#include "macro/fe/distributed_system.h"
#include "macro/fe/newton_continuation.h"
#include "macro/fe/refine_and_transfer.h"
#include "macro/io/vtu_output.h"
#include "macro/material/regularised_law.h"

namespace softglass::macro::fe {

using namespace dealii;

namespace {

// The boundary velocity as a deal.II function of the 3 components (u, v, p).
class BoundaryVelocity : public Function<2> {
 public:
  explicit BoundaryVelocity(std::function<Tensor<1, 2>(const Point<2>&)> f)
      : Function<2>(3), f_(std::move(f)) {}
  void vector_value(const Point<2>& p, Vector<double>& values) const override {
    const Tensor<1, 2> u = f_(p);
    values(0) = u[0];
    values(1) = u[1];
    values(2) = 0.0;
  }

 private:
  std::function<Tensor<1, 2>(const Point<2>&)> f_;
};

}  // namespace

class StokesFlowSolver::Implementation {
 public:
  Implementation(const Triangulation<2>& base, std::shared_ptr<const ShearLaw> law,
                 const SolverSettings& settings)
      : law_(std::move(law)),
        settings_(settings),
        communicator_(settings.mesh_communicator),
        system_(communicator_, MatrixKind::symmetric_indefinite),
        triangulation_(communicator_),
        mapping_(2),
        fe_(FE_Q<2>(2), 2, FE_Q<2>(1), 1),
        dof_handler_(triangulation_),
        newton_(
            "Stokes Newton", LineSearch::residual_halving, system_, zero_constraints_,
            [this](const RegularisedLaw& regularised, const VectorType& u, bool with_matrix,
                   double tangent_floor) {
              assemble_system(regularised, u, with_matrix, tangent_floor);
            },
            *law_, settings) {
    coarse_.copy_triangulation(base);
  }

  StokesResult run(const StokesDrive& drive);
  std::vector<Tensor<1, 2>> velocity_at(const std::vector<Point<2>>& points) const;
  void output_results(const std::filesystem::path& file) const;

 private:
  VectorType setup_system();
  void assemble_system(const RegularisedLaw& law, const VectorType& u, bool with_matrix,
                       double tangent_floor);
  StokesOutputs evaluate() const;
  void refine_mesh(bool uniform);

  std::shared_ptr<const ShearLaw> law_;
  SolverSettings settings_;
  MPI_Comm communicator_;
  DistributedSystem system_;  // matrix, factorisation, residual of the current mesh
  StokesDrive drive_;
  Triangulation<2> coarse_;  // the scene's mesh, unrefined
  parallel::distributed::Triangulation<2> triangulation_;
  MappingQ<2> mapping_;
  FESystem<2> fe_;
  DoFHandler<2> dof_handler_;
  AffineConstraints<double> constraints_, zero_constraints_;
  VectorType solution_;  // owned entries only
  std::unique_ptr<RegularisedLaw> regularised_;
  VectorType previous_coarse_;
  double previous_rate_ = 0.0;
  NewtonContinuation newton_;  // declared last: it refers to the members above
};

VectorType StokesFlowSolver::Implementation::setup_system() {
  dof_handler_.distribute_dofs(fe_);
  system_.set_dofs(dof_handler_);
  const FEValuesExtractors::Vector velocities(0);
  const FEValuesExtractors::Scalar transverse(1), pressure(2);
  // Pin one pressure unknown when no boundary is free (closed domain): the
  // lowest-numbered pressure dof of all ranks.
  bool closed = true;
  for (const auto id : triangulation_.get_boundary_ids())
    closed = closed && drive_.velocity.count(id) > 0;
  const IndexSet pressure_dofs = DoFTools::extract_dofs(dof_handler_, fe_.component_mask(pressure));
  const types::global_dof_index pinned = Utilities::MPI::min(
      pressure_dofs.n_elements() > 0 ? pressure_dofs.nth_index_in_set(0)
                                     : std::numeric_limits<types::global_dof_index>::max(),
      communicator_);
  for (auto [constraints, homogeneous] :
       {std::pair{&constraints_, false}, std::pair{&zero_constraints_, true}}) {
    constraints->clear();
    constraints->reinit(system_.relevant);
    DoFTools::make_hanging_node_constraints(dof_handler_, *constraints);
    for (const auto& [id, f] : drive_.velocity) {
      if (homogeneous) {
        VectorTools::interpolate_boundary_values(mapping_, dof_handler_, id,
                                                 Functions::ZeroFunction<2>(3), *constraints,
                                                 fe_.component_mask(velocities));
      } else {
        VectorTools::interpolate_boundary_values(mapping_, dof_handler_, id, BoundaryVelocity(f),
                                                 *constraints, fe_.component_mask(velocities));
      }
    }
    for (const auto id : drive_.straight_outflow) {
      VectorTools::interpolate_boundary_values(mapping_, dof_handler_, id,
                                               Functions::ZeroFunction<2>(3), *constraints,
                                               fe_.component_mask(transverse));
    }
    if (closed && system_.relevant.is_element(pinned)) constraints->add_line(pinned);
    constraints->close();
  }
  return system_.make_matrix(dof_handler_, zero_constraints_);
}

void StokesFlowSolver::Implementation::assemble_system(const RegularisedLaw& law,
                                                       const VectorType& u, bool with_matrix,
                                                       double tangent_floor) {
  if (with_matrix) system_.matrix = 0.0;
  system_.residual = 0.0;
  const VectorType& field = system_.readable(u);
  const QGauss<2> quadrature(3);
  FEValues<2> fe_values(mapping_, fe_, quadrature,
                        update_values | update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector velocities(0);
  const FEValuesExtractors::Scalar pressure(2);
  const unsigned n = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_residual(n);
  std::vector<SymmetricTensor<2, 2>> strain(quadrature.size()), phi_d(n);
  std::vector<double> p(quadrature.size()), div_u(quadrature.size()), phi_div(n), phi_p(n);
  std::vector<types::global_dof_index> dofs(n);
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values[velocities].get_function_symmetric_gradients(field, strain);
    fe_values[velocities].get_function_divergences(field, div_u);
    fe_values[pressure].get_function_values(field, p);
    cell_matrix = 0.0;
    cell_residual = 0.0;
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const double rate = std::sqrt(2.0 * (strain[q] * strain[q]));
      const Viscosity eta = law.viscosity(rate);
      // 4η'/γ̇ (D:D(δu))(D:D(v)) = 2(τ' − η) (N:D(δu))(N:D(v)), τ' floored.
      const double anisotropy =
          rate > 0.0 ? 2.0 * std::max(eta.derivative * rate, (tangent_floor - 1.0) * eta.value) *
                           2.0 / (rate * rate)
                     : 0.0;
      const double jxw = fe_values.JxW(q);
      for (unsigned k = 0; k < n; ++k) {
        phi_d[k] = fe_values[velocities].symmetric_gradient(k, q);
        phi_div[k] = fe_values[velocities].divergence(k, q);
        phi_p[k] = fe_values[pressure].value(k, q);
      }
      for (unsigned i = 0; i < n; ++i) {
        cell_residual(i) +=
            (2.0 * eta.value * (strain[q] * phi_d[i]) - p[q] * phi_div[i] - phi_p[i] * div_u[q]) *
            jxw;
        if (!with_matrix) continue;
        const double n_i = strain[q] * phi_d[i];
        for (unsigned j = 0; j < n; ++j) {
          cell_matrix(i, j) +=
              (2.0 * eta.value * (phi_d[j] * phi_d[i]) + anisotropy * n_i * (strain[q] * phi_d[j]) -
               phi_p[j] * phi_div[i] - phi_p[i] * phi_div[j]) *
              jxw;
        }
      }
    }
    cell->get_dof_indices(dofs);
    if (with_matrix) {
      zero_constraints_.distribute_local_to_global(cell_matrix, cell_residual, dofs, system_.matrix,
                                                   system_.residual);
    } else {
      zero_constraints_.distribute_local_to_global(cell_residual, dofs, system_.residual);
    }
  }
  if (with_matrix) system_.matrix.compress(VectorOperation::add);
  system_.residual.compress(VectorOperation::add);
}

StokesOutputs StokesFlowSolver::Implementation::evaluate() const {
  const types::boundary_id force_id = drive_.force_boundary, pressure_id = drive_.pressure_boundary;
  const VectorType& field = system_.readable(solution_);
  const QGauss<2> quadrature(3);
  FEValues<2> fe_values(mapping_, fe_, quadrature, update_gradients | update_JxW_values);
  const QGauss<1> face_quadrature(3);
  FEFaceValues<2> face_values(
      mapping_, fe_, face_quadrature,
      update_values | update_gradients | update_normal_vectors | update_JxW_values);
  const FEValuesExtractors::Vector velocities(0);
  const FEValuesExtractors::Scalar pressure(2);
  std::vector<SymmetricTensor<2, 2>> strain(quadrature.size()), face_strain(face_quadrature.size());
  std::vector<double> face_p(face_quadrature.size());
  // This rank's dissipation, area, yielded area, force (x, y), pressure
  // integral and the length it is taken over.
  std::array<double, 7> sums{};
  auto& [dissipation, area, yielded, force_x, force_y, pressure_sum, pressure_length] = sums;
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values[velocities].get_function_symmetric_gradients(field, strain);
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const double rate = std::sqrt(2.0 * (strain[q] * strain[q]));
      const double tau = regularised_->stress(rate);
      dissipation += tau * rate * fe_values.JxW(q);
      area += fe_values.JxW(q);
      if (tau > law_->yield_stress()) yielded += fe_values.JxW(q);
    }
    for (const unsigned f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary()) continue;
      const auto id = cell->face(f)->boundary_id();
      if (id != force_id && id != pressure_id) continue;
      face_values.reinit(cell, f);
      face_values[velocities].get_function_symmetric_gradients(field, face_strain);
      face_values[pressure].get_function_values(field, face_p);
      for (const unsigned q : face_values.quadrature_point_indices()) {
        const double rate = std::sqrt(2.0 * (face_strain[q] * face_strain[q]));
        const double eta = regularised_->viscosity(rate).value;
        const Tensor<1, 2> normal = face_values.normal_vector(q);  // out of the fluid
        if (id == force_id) {
          // On the body: −σ n with n out of the fluid is the body's outward
          // normal reversed, so the force on the body is ∫ σ (−n_body) = −∫ σ n.
          const Tensor<1, 2> traction = -face_p[q] * normal + 2.0 * eta * (face_strain[q] * normal);
          force_x -= traction[0] * face_values.JxW(q);
          force_y -= traction[1] * face_values.JxW(q);
        }
        if (id == pressure_id) {
          pressure_sum += face_p[q] * face_values.JxW(q);
          pressure_length += face_values.JxW(q);
        }
      }
    }
  }
  Utilities::MPI::sum(ArrayView<const double>(sums), communicator_, ArrayView<double>(sums));
  StokesOutputs out;
  out.dissipation = dissipation;
  out.yielded_fraction = yielded / area;
  out.force = Tensor<1, 2>({force_x, force_y});
  if (pressure_length > 0.0) out.mean_pressure = pressure_sum / pressure_length;
  if (!drive_.probes.empty()) out.probes = velocity_at(drive_.probes);
  return out;
}

// Uniform, or the top fraction of the Kelly indicator of the velocity plus
// every cell a yield surface crosses (as in the scalar solver).
void StokesFlowSolver::Implementation::refine_mesh(bool uniform) {
  const VectorType& field = system_.readable(solution_);
  if (uniform) {
    triangulation_.set_all_refine_flags();
  } else {
    const FEValuesExtractors::Vector velocities(0);
    Vector<float> indicators(triangulation_.n_active_cells());
    KellyErrorEstimator<2>::estimate(mapping_, dof_handler_, QGauss<1>(3),
                                     std::map<types::boundary_id, const Function<2>*>(), field,
                                     indicators, fe_.component_mask(velocities));
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        triangulation_, indicators, settings_.refine_fraction, 0.0);
    const QGauss<2> quadrature(3);
    FEValues<2> fe_values(mapping_, fe_, quadrature, update_gradients);
    std::vector<SymmetricTensor<2, 2>> strain(quadrature.size());
    for (const auto& cell : owned_cells(dof_handler_)) {
      fe_values.reinit(cell);
      fe_values[velocities].get_function_symmetric_gradients(field, strain);
      bool above = false, below = false;
      for (const unsigned q : fe_values.quadrature_point_indices()) {
        const double rate = std::sqrt(2.0 * (strain[q] * strain[q]));
        (regularised_->stress(rate) > law_->yield_stress() ? above : below) = true;
      }
      if (above && below && law_->yield_stress() > 0.0) cell->set_refine_flag();
    }
  }
  refine_and_transfer(triangulation_, dof_handler_, field, solution_,
                      [this] { return setup_system(); });
  constraints_.distribute(solution_);
}

StokesResult StokesFlowSolver::Implementation::run(const StokesDrive& drive) {
  const auto start = std::chrono::steady_clock::now();
  drive_ = drive;
  const double rate_c = drive.characteristic_rate;
  StokesResult result;
  // The same first mesh (and partition) at every point: the previous point's
  // solution on it is a valid start.
  triangulation_.clear();
  triangulation_.copy_triangulation(coarse_);
  triangulation_.refine_global(settings_.global_refinements);
  solution_ = setup_system();
  const double target = settings_.relative_rate_scale * rate_c;
  const bool warm =
      previous_rate_ > 0.0 && previous_coarse_.locally_owned_elements() == system_.owned;
  if (warm) {
    solution_ = previous_coarse_;
    solution_ *= rate_c / previous_rate_;
  }
  constraints_.distribute(solution_);
  // Nested iteration: the continuation on the coarse mesh down to 10ε and ε.
  result.iterations +=
      newton_.continuation(kContinuationFactor * target,
                           warm ? kContinuationFactor * target : rate_c, solution_, regularised_);
  result.at_ten_epsilon = evaluate();
  result.iterations += newton_.continuation(target, target, solution_, regularised_);
  result.first_mesh = evaluate();
  previous_coarse_ = solution_;
  previous_rate_ = rate_c;

  // One uniform refinement, then the adaptive cycles; Newton at ε after each,
  // from the transferred solution. The discretisation estimate is the change
  // over the last refinement.
  result.coarse = result.first_mesh;
  refine_mesh(true);
  result.iterations += newton_.solve_damped_on_failure(*regularised_, solution_);
  for (unsigned cycle = 0; cycle < settings_.adaptive_cycles; ++cycle) {
    result.coarse = evaluate();
    refine_mesh(false);
    result.iterations += newton_.solve_damped_on_failure(*regularised_, solution_);
  }
  result.value = evaluate();
  result.cells = triangulation_.n_global_active_cells();
  result.dofs = dof_handler_.n_dofs();
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// Every rank gets the velocity at every point, wherever its cell lives.
std::vector<Tensor<1, 2>> StokesFlowSolver::Implementation::velocity_at(
    const std::vector<Point<2>>& points) const {
  Utilities::MPI::RemotePointEvaluation<2> cache;
  const auto values = VectorTools::point_values<3>(mapping_, dof_handler_,
                                                   system_.readable(solution_), points, cache);
  if (!cache.all_points_found())
    throw NumericalError("velocity requested at a point outside the domain");
  std::vector<Tensor<1, 2>> result;
  for (const auto& v : values) result.push_back(Tensor<1, 2>({v[0], v[1]}));
  return result;
}

// One VTU file however many ranks share the mesh (MPI-IO); every rank of the
// mesh's communicator calls this with the same file name.
void StokesFlowSolver::Implementation::output_results(const std::filesystem::path& file) const {
  const VectorType& field = system_.readable(solution_);
  const unsigned n_cells = triangulation_.n_active_cells();
  Vector<double> rate(n_cells), tau(n_cells), yielded(n_cells);
  const QGauss<2> quadrature(3);
  FEValues<2> fe_values(mapping_, fe_, quadrature, update_gradients);
  const FEValuesExtractors::Vector velocities(0);
  std::vector<SymmetricTensor<2, 2>> strain(quadrature.size());
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values[velocities].get_function_symmetric_gradients(field, strain);
    const unsigned c = cell->active_cell_index();
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const double g = std::sqrt(2.0 * (strain[q] * strain[q])), t = regularised_->stress(g);
      rate(c) += g / quadrature.size();
      tau(c) += t / quadrature.size();
      yielded(c) += t > law_->yield_stress() ? 1.0 / quadrature.size() : 0.0;
    }
  }
  std::vector<std::string> names{"velocity", "velocity", "pressure"};
  std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds{
      DataComponentInterpretation::component_is_part_of_vector,
      DataComponentInterpretation::component_is_part_of_vector,
      DataComponentInterpretation::component_is_scalar};
  DataOut<2> data_out;
  data_out.attach_dof_handler(dof_handler_);
  data_out.add_data_vector(field, names, DataOut<2>::type_dof_data, kinds);
  data_out.add_data_vector(rate, "shear_rate");
  data_out.add_data_vector(tau, "stress");
  data_out.add_data_vector(yielded, "yielded");
  data_out.build_patches(mapping_, 2);
  io::write_vtu(data_out, file, communicator_);
}

StokesFlowSolver::StokesFlowSolver(const Triangulation<2>& base_mesh,
                                   std::shared_ptr<const ShearLaw> law,
                                   const SolverSettings& settings)
    : impl_(std::make_unique<Implementation>(base_mesh, std::move(law), settings)) {}

StokesFlowSolver::~StokesFlowSolver() = default;

StokesResult StokesFlowSolver::run(const StokesDrive& drive) {
  return impl_->run(drive);
}

std::vector<Tensor<1, 2>> StokesFlowSolver::velocity_at(const std::vector<Point<2>>& points) const {
  return impl_->velocity_at(points);
}

void StokesFlowSolver::output_results(const std::filesystem::path& file) const {
  impl_->output_results(file);
}

}  // namespace softglass::macro::fe
