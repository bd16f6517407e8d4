// The scalar flow solver (scalar_flow_solver.h). The one heavy translation unit
// of the reduced scenes: every deal.II template it needs is instantiated here,
// for dim = 1 and 2, and nowhere else.
//
// The mathematics, in the order of the functions below.
//
// Regularised method. With a regularised viscosity η_ε (regularised_law.h) the
// functional J of scalar_problem.h is smooth and strictly convex, and its
// minimiser solves the nonlinear problem
//
//     R(u)(v) = ∫ ρ s² η_ε(γ̇) ∇u·∇v dx − ∫ ρ f v dx = 0,     γ̇ = s|∇u|.
//
// Newton's method linearises the flux q = ρ s² η_ε ∇u about the current u: with
// n = ∇u/|∇u| and the tangent τ' = dτ/dγ̇ = η + γ̇ dη/dγ̇,
//
//     ∂q/∂∇u = ρ s² [ η (I − n⊗n) + τ' n⊗n ],
//
// symmetric positive definite (τ' > 0 for every regularised law), so each
// Newton step is a weighted anisotropic Laplace problem, solved by a sparse
// direct factorisation. The step is a descent direction of J, so the line
// search minimises J along it (LineSearch::energy_slope of
// newton_continuation.h, which also holds the modified tangent and the
// continuation in ε).
//
// Slip walls (scalar_problem.h) add the wall's potential ∫_Γs ρ D(V_s) ds to
// J, so R gains ∫_Γs ρ s σ_ε(V_s) v ds and the Newton matrix
// ∫_Γs ρ s² σ_ε'(V_s) δu v ds, with the slip law regularised at
// ε_V = ε · WallSlip::length (slip_law.h): a symmetric positive addition, the
// consistent Jacobian of the residual, so Newton converges as quadratically
// as without slip. The slip walls are left out of the Dirichlet constraints;
// their value in Drive::boundary_values is the wall's u_w.
//
// Continuation. The solver starts at ε = γ̇_c (nearly a Newtonian fluid with
// the scene's viscosity scale) and divides ε by 10 per stage down to the
// target. The last two stages (10ε and ε) give the regularisation error
// estimate: the outputs converge like O(ε) (docs/macro.md), so the error at ε is
// about their difference / 9.
//
// Augmented Lagrangian. The alternative to regularising: ALG2 on the
// unregularised law (augmented_lagrangian.h), started from a coarsely
// regularised solution.
//
// Adaptivity. After each solve the Kelly indicator (the jump of the normal
// derivative across faces) ranks the cells; the top fraction is refined, and so
// is every cell the yield surface crosses (some quadrature points yielded and
// some not). The discretisation error is estimated as the change of each output
// over the last cycle.
//
// Parallel. The 2D sections live on a distributed triangulation (p4est) over
// the ranks of settings.mesh_communicator: each rank assembles its own cells
// into Trilinos' distributed matrix and vectors, the integrals are summed over
// the ranks, and the linear systems are solved by MUMPS (direct_solver.h), a
// parallel sparse direct solver — the Newton matrices span the
// viscosity range of a regularised plug (τ_y/ε against K γ̇ⁿ⁻¹, 10⁴ and more),
// which an iterative solver would have to be preconditioned for, and ALG2
// reuses one factorisation thousands of times. Every decision (Newton's stop,
// the line search, the cells to refine) is taken on global quantities, so all
// ranks take the same path and the result does not depend on their number
// beyond rounding. A 1D section (a few hundred unknowns) stays on one rank.
#include "macro/fe/scalar_flow_solver.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>

#include "common/errors.h"
#include "macro/fe/augmented_lagrangian.h"
#include "macro/fe/distributed_system.h"
#include "macro/fe/newton_continuation.h"
#include "macro/fe/refine_and_transfer.h"
#include "macro/io/vtu_output.h"
#include "macro/material/regularised_law.h"

namespace softglass::macro::fe {

using namespace dealii;

namespace {

// The mesh of a section: distributed in 2D; a 1D section stays serial (p4est
// has no 1D forests, and a line of a few hundred cells gains nothing).
template <int dim>
using SectionMesh =
    std::conditional_t<dim == 1, Triangulation<1>, parallel::distributed::Triangulation<dim>>;

template <int dim>
std::unique_ptr<SectionMesh<dim>> make_section_mesh(MPI_Comm communicator) {
  if constexpr (dim == 1) {
    return std::make_unique<Triangulation<1>>();
  } else {
    return std::make_unique<parallel::distributed::Triangulation<dim>>(communicator);
  }
}

Outputs difference(const Outputs& a, const Outputs& b, double divisor) {
  return {.flow = std::abs(a.flow - b.flow) / divisor,
          .dissipation = std::abs(a.dissipation - b.dissipation) / divisor,
          .yielded_fraction = std::abs(a.yielded_fraction - b.yielded_fraction) / divisor,
          .boundary = std::abs(a.boundary - b.boundary) / divisor,
          .max_value = std::abs(a.max_value - b.max_value) / divisor};
}

}  // namespace

template <int dim>
class ScalarFlowSolver<dim>::Implementation {
 public:
  Implementation(const Triangulation<dim>& base_mesh, unsigned mapping_degree,
                 const SectionWeights& weights, std::shared_ptr<const ShearLaw> law,
                 const WallSlip& slip, const SolverSettings& settings)
      : weights_(weights),
        law_(std::move(law)),
        slip_(slip),
        settings_(settings),
        communicator_(dim == 1 ? MPI_COMM_SELF : settings.mesh_communicator),
        system_(communicator_, MatrixKind::positive_definite),
        triangulation_(make_section_mesh<dim>(communicator_)),
        mapping_(mapping_degree),
        fe_(settings.fe_degree),
        dof_handler_(*triangulation_),
        newton_(
            "Newton", LineSearch::energy_slope, system_, zero_constraints_,
            [this](const RegularisedLaw& regularised, const VectorType& u, bool with_matrix,
                   double tangent_floor) {
              assemble_system(regularised, u, with_matrix, tangent_floor);
            },
            *law_, settings),
        augmented_lagrangian_({mapping_, fe_, dof_handler_, weights_, communicator_}, system_,
                              constraints_, *law_, settings) {
    require(!slip_.any() || settings.method == Method::regularised,
            "solver: method = augmented-lagrangian cannot take slip walls (its u-step is linear "
            "with the walls' values fixed); allowed with slip walls: method = regularised");
    coarse_.copy_triangulation(base_mesh);
  }

  PointResult run(const Drive& drive, const BoundaryFunctional& boundary);
  void output_results(const std::filesystem::path& file) const;

 private:
  // --- setup -------------------------------------------------------------
  bool setup_base_mesh();
  VectorType setup_system();
  void make_constraints();
  void impose_boundary_values();

  // --- the nonlinear solve, by the chosen method -----------------------------
  unsigned solve(bool warm, const BoundaryFunctional& boundary, Outputs& before);
  unsigned solve_after_refinement();
  Outputs regularisation_error(const Outputs& value, const Outputs& before) const;

  // --- regularised method --------------------------------------------------
  void assemble_system(const RegularisedLaw& law, const VectorType& u, bool with_matrix,
                       double tangent_floor = 0.0);
  /// Continuation from ε = start_scale to target_scale from the current u;
  /// leaves the law at the target in regularised_.
  unsigned solve_with_continuation(double target_scale, double start_scale) {
    return newton_.continuation(target_scale, start_scale, solution_, regularised_);
  }

  unsigned solve_regularised(bool warm, const BoundaryFunctional& boundary, Outputs& before);
  unsigned solve_regularised_after_refinement();

  // --- augmented Lagrangian -------------------------------------------------
  unsigned solve_augmented_lagrangian(const std::function<void()>& record = {});

  // --- outputs and adaptivity --------------------------------------------
  Outputs evaluate(const BoundaryFunctional& boundary) const;
  void refine_mesh();

  /// The stress of the current solution at a shear rate: the regularised law
  /// while regularising, the rate field of ALG2 otherwise.
  double stress(double rate) const {
    return regularised_ ? regularised_->stress(rate) : law_->stress(rate);
  }

  /// The slip velocity V_s = s (u − u_w) on slip wall `id` and the wall
  /// stress of the law regularised at ε_V = ε · length (ε: `rate_scale`).
  struct WallState {
    double velocity;
    WallStress stress;
  };
  WallState wall_state(const Point<dim>& x, double u, types::boundary_id id,
                       double rate_scale) const {
    const double velocity = s(x) * (u - drive_.boundary_values.at(id));
    return {velocity, slip_.law->regularised(velocity, rate_scale * slip_.length)};
  }
  bool slips(const typename DoFHandler<dim>::active_cell_iterator& cell, unsigned face) const {
    return slip_.any() && cell->face(face)->at_boundary() &&
           slip_.walls.count(cell->face(face)->boundary_id()) > 0;
  }

  double rho(const Point<dim>& x) const { return weights_.rho(x[0]); }
  double s(const Point<dim>& x) const { return weights_.s(x[0]); }

  /// Shear rate, stress and whether the material yields at quadrature point x
  /// (number k over this rank's cells): from the gradient while regularising;
  /// ALG2 keeps its rate field γ, exactly zero in rigid regions.
  struct LocalState {
    double rate, stress;
    bool yielded;
  };
  LocalState local_state(const Point<dim>& x, const Tensor<1, dim>& gradient, std::size_t k) const {
    const double rate = regularised_ ? s(x) * gradient.norm() : augmented_lagrangian_.rate(k);
    const double tau = stress(rate);
    return {rate, tau, regularised_ ? tau > law_->yield_stress() : rate > 0.0};
  }

  SectionWeights weights_;
  std::shared_ptr<const ShearLaw> law_;
  WallSlip slip_;
  SolverSettings settings_;
  Drive drive_;
  MPI_Comm communicator_;
  DistributedSystem system_;  // matrix, factorisation, residual of the current mesh

  Triangulation<dim> coarse_;  // the scene's mesh, unrefined
  std::unique_ptr<SectionMesh<dim>> triangulation_;
  MappingQ<dim> mapping_;
  FE_Q<dim> fe_;
  DoFHandler<dim> dof_handler_;
  AffineConstraints<double> constraints_;       // hanging nodes + Dirichlet data
  AffineConstraints<double> zero_constraints_;  // hanging nodes + homogeneous Dirichlet
  VectorType solution_;                         // owned entries only

  // The regularised law of the last solve (null after ALG2).
  std::unique_ptr<RegularisedLaw> regularised_;

  // The previous operating point's solution on the (refined) base mesh, and its
  // characteristic rate: the warm start of the next point.
  VectorType previous_base_solution_;
  double previous_rate_ = 0.0;

  // The two methods; declared last: they refer to the members above.
  NewtonContinuation newton_;
  AugmentedLagrangian<dim> augmented_lagrangian_;
};

// --- setup ----------------------------------------------------------------

// Distributes the dofs, builds the constraints and the matrix's sparsity on
// the current mesh, and returns a zero vector laid out for them.
template <int dim>
VectorType ScalarFlowSolver<dim>::Implementation::setup_system() {
  dof_handler_.distribute_dofs(fe_);
  system_.set_dofs(dof_handler_);
  make_constraints();
  return system_.make_matrix(dof_handler_, zero_constraints_);
}

// The same base mesh (and, distributed, the same partition) at every point,
// so that the previous point's solution is a valid start: if there is one,
// u starts as its profile, rescaled by the ratio of shear rates (true: warm).
template <int dim>
bool ScalarFlowSolver<dim>::Implementation::setup_base_mesh() {
  triangulation_->clear();
  triangulation_->copy_triangulation(coarse_);
  triangulation_->refine_global(settings_.global_refinements);
  solution_ = setup_system();
  const bool warm =
      previous_rate_ > 0.0 && previous_base_solution_.locally_owned_elements() == system_.owned;
  if (warm) {
    solution_ = previous_base_solution_;
    solution_ *= drive_.characteristic_rate / previous_rate_;
  }
  impose_boundary_values();
  return warm;
}

template <int dim>
void ScalarFlowSolver<dim>::Implementation::make_constraints() {
  for (auto [constraints, homogeneous] :
       {std::pair{&constraints_, false}, std::pair{&zero_constraints_, true}}) {
    constraints->clear();
    constraints->reinit(system_.relevant);
    DoFTools::make_hanging_node_constraints(dof_handler_, *constraints);
    for (const auto& [id, value] : drive_.boundary_values) {
      if (slip_.walls.count(id) > 0) continue;  // Robin, not Dirichlet
      VectorTools::interpolate_boundary_values(
          mapping_, dof_handler_, id, Functions::ConstantFunction<dim>(homogeneous ? 0.0 : value),
          *constraints);
    }
    constraints->close();
  }
}

template <int dim>
void ScalarFlowSolver<dim>::Implementation::impose_boundary_values() {
  constraints_.distribute(solution_);
}

// --- regularised method -----------------------------------------------------

// Residual R(u)(φ_i) at `u` and, if asked, the Newton matrix, condensed with
// the homogeneous constraints (the update vanishes on Dirichlet boundaries).
template <int dim>
void ScalarFlowSolver<dim>::Implementation::assemble_system(const RegularisedLaw& law,
                                                            const VectorType& u, bool with_matrix,
                                                            double tangent_floor) {
  if (with_matrix) system_.matrix = 0.0;
  system_.residual = 0.0;
  const VectorType& field = system_.readable(u);
  const QGauss<dim> quadrature(fe_.degree + 1);
  FEValues<dim> fe_values(
      mapping_, fe_, quadrature,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  const unsigned n = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_residual(n);
  std::vector<Tensor<1, dim>> gradients(quadrature.size());
  std::vector<types::global_dof_index> dofs(n);
  const QGauss<dim - 1> face_quadrature(fe_.degree + 1);
  FEFaceValues<dim> face_values(mapping_, fe_, face_quadrature,
                                update_values | update_quadrature_points | update_JxW_values);
  std::vector<double> face_u(face_quadrature.size());

  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(field, gradients);
    cell_matrix = 0.0;
    cell_residual = 0.0;
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const Point<dim>& x = fe_values.quadrature_point(q);
      const double sq = s(x), weight = rho(x) * sq * sq * fe_values.JxW(q);
      const double g = gradients[q].norm(), rate = sq * g;
      const Viscosity eta = law.viscosity(rate);
      // n = ∇u/|∇u|; at rest the anisotropic part vanishes (γ̇ dη/dγ̇ = 0).
      const Tensor<1, dim> direction = g > 0.0 ? gradients[q] / g : Tensor<1, dim>();
      // τ' − η, with τ' raised to tangent_floor·η if it is smaller (newton_continuation.h).
      const double anisotropy = std::max(eta.derivative * rate, (tangent_floor - 1.0) * eta.value);
      const double f = drive_.source * rho(x) * fe_values.JxW(q);
      for (unsigned i = 0; i < n; ++i) {
        const Tensor<1, dim> grad_i = fe_values.shape_grad(i, q);
        cell_residual(i) +=
            weight * eta.value * (gradients[q] * grad_i) - f * fe_values.shape_value(i, q);
        if (!with_matrix) continue;
        const double n_i = direction * grad_i;
        for (unsigned j = 0; j < n; ++j) {
          const Tensor<1, dim> grad_j = fe_values.shape_grad(j, q);
          cell_matrix(i, j) +=
              weight * (eta.value * (grad_i * grad_j) + anisotropy * n_i * (direction * grad_j));
        }
      }
    }
    // Slip walls: ∫ ρ s σ_ε(V) φ_i ds and ∫ ρ s² σ_ε'(V) φ_i φ_j ds.
    for (const unsigned f : cell->face_indices()) {
      if (!slips(cell, f)) continue;
      face_values.reinit(cell, f);
      face_values.get_function_values(field, face_u);
      for (const unsigned q : face_values.quadrature_point_indices()) {
        const Point<dim>& x = face_values.quadrature_point(q);
        const WallState wall =
            wall_state(x, face_u[q], cell->face(f)->boundary_id(), law.rate_scale());
        const double weight = rho(x) * s(x) * face_values.JxW(q);
        for (unsigned i = 0; i < n; ++i) {
          const double phi_i = face_values.shape_value(i, q);
          cell_residual(i) += weight * wall.stress.value * phi_i;
          if (!with_matrix) continue;
          for (unsigned j = 0; j < n; ++j)
            cell_matrix(i, j) +=
                weight * s(x) * wall.stress.derivative * phi_i * face_values.shape_value(j, q);
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

// --- the nonlinear solve, by the chosen method ------------------------------

// On the base mesh; `before` gets the outputs the regularisation error is
// estimated from.
template <int dim>
unsigned ScalarFlowSolver<dim>::Implementation::solve(bool warm, const BoundaryFunctional& boundary,
                                                      Outputs& before) {
  if (settings_.method == Method::regularised) return solve_regularised(warm, boundary, before);
  // ALG2 starts from a coarsely regularised solution (ε = γ̇_c/100) when cold.
  const double rate_c = drive_.characteristic_rate;
  const unsigned iterations = warm ? 0 : solve_with_continuation(1e-2 * rate_c, rate_c);
  return iterations + solve_augmented_lagrangian([&] { before = evaluate({}); });
}

template <int dim>
unsigned ScalarFlowSolver<dim>::Implementation::solve_after_refinement() {
  return settings_.method == Method::regularised ? solve_regularised_after_refinement()
                                                 : solve_augmented_lagrangian();
}

// Regularised: the O(ε) law, error ≈ (value at 10ε − value)/9. ALG2: the 1/k
// law of its iterations (augmented_lagrangian.h).
template <int dim>
Outputs ScalarFlowSolver<dim>::Implementation::regularisation_error(const Outputs& value,
                                                                    const Outputs& before) const {
  return difference(value, before,
                    settings_.method == Method::regularised
                        ? kContinuationFactor - 1.0
                        : augmented_lagrangian_.error_divisor());
}

// Cold start: continuation from ε = γ̇_c down to 10ε. Warm start: straight to
// 10ε, falling back to the full continuation if Newton fails. Then ε.
template <int dim>
unsigned ScalarFlowSolver<dim>::Implementation::solve_regularised(
    bool warm, const BoundaryFunctional& boundary, Outputs& before) {
  const double rate_c = drive_.characteristic_rate;
  const double target = settings_.relative_rate_scale * rate_c;
  const double coarse = kContinuationFactor * target;
  unsigned iterations = 0;
  try {
    iterations += solve_with_continuation(coarse, warm ? coarse : rate_c);
  } catch (const NumericalError&) {
    if (!warm) throw;
    solution_ = 0.0;
    impose_boundary_values();
    iterations += solve_with_continuation(coarse, rate_c);
  }
  before = evaluate(boundary);
  return iterations + solve_with_continuation(target, target);
}

// On the refined mesh Newton starts from the interpolated solution; if that
// fails, the cold start of the base mesh runs again: the whole continuation
// from u = 0 and ε = γ̇_c. (Neither one stage at 10ε nor the continuation from
// the interpolated field suffices: near a yield surface the refinement moved,
// that field solves neither problem, and at Bingham numbers of 10² and more
// Newton steps from it overshoot by orders of magnitude at every ε; measured
// with bench/solver_envelope.sh.)
template <int dim>
unsigned ScalarFlowSolver<dim>::Implementation::solve_regularised_after_refinement() {
  try {
    return newton_.solve(*regularised_, solution_);
  } catch (const NumericalError&) {
    solution_ = 0.0;
    impose_boundary_values();
    const double rate_c = drive_.characteristic_rate;
    return solve_with_continuation(settings_.relative_rate_scale * rate_c, rate_c);
  }
}

// ALG2 from the current u; the regularised law u solves (if any) starts its
// multiplier, and evaluate() reads ALG2's rate field from then on.
template <int dim>
unsigned ScalarFlowSolver<dim>::Implementation::solve_augmented_lagrangian(
    const std::function<void()>& record) {
  const std::unique_ptr<RegularisedLaw> start_law = std::move(regularised_);
  return augmented_lagrangian_.solve(solution_, drive_, start_law.get(), record);
}

// --- outputs and adaptivity ----------------------------------------------------

template <int dim>
Outputs ScalarFlowSolver<dim>::Implementation::evaluate(const BoundaryFunctional& boundary) const {
  const VectorType& field = system_.readable(solution_);
  const QGauss<dim> quadrature(fe_.degree + 1);
  FEValues<dim> fe_values(
      mapping_, fe_, quadrature,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  const QGauss<dim - 1> face_quadrature(fe_.degree + 1);
  FEFaceValues<dim> face_values(
      mapping_, fe_, face_quadrature,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  std::vector<double> values(quadrature.size()), face_u(face_quadrature.size());
  std::vector<Tensor<1, dim>> gradients(quadrature.size()), face_gradients(face_quadrature.size());
  // This rank's share of flow, dissipation, boundary integral, volume, yielded volume.
  std::array<double, 5> sums{};
  auto& [flow, dissipation, boundary_sum, volume, yielded] = sums;
  std::size_t k = 0;
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values.get_function_values(field, values);
    fe_values.get_function_gradients(field, gradients);
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const Point<dim>& x = fe_values.quadrature_point(q);
      const double w = rho(x) * fe_values.JxW(q);
      const LocalState local = local_state(x, gradients[q], k);
      flow += values[q] * w;
      dissipation += local.stress * local.rate * w;
      volume += w;
      if (local.yielded) yielded += w;
      ++k;
    }
    if (!cell->at_boundary()) continue;
    for (const unsigned f : cell->face_indices()) {
      // The walls' dissipation σ_w V_s (slip walls exist only with the
      // regularised method: the constructor refuses them to ALG2).
      if (slips(cell, f)) {
        face_values.reinit(cell, f);
        face_values.get_function_values(field, face_u);
        for (const unsigned q : face_values.quadrature_point_indices()) {
          const Point<dim>& x = face_values.quadrature_point(q);
          const WallState wall = wall_state(x, face_u[q], cell->face(f)->boundary_id(),
                                            regularised_->rate_scale());
          dissipation += wall.stress.value * wall.velocity * rho(x) * face_values.JxW(q);
        }
      }
      if (!boundary.integrand || !cell->face(f)->at_boundary() ||
          cell->face(f)->boundary_id() != boundary.id)
        continue;
      face_values.reinit(cell, f);
      face_values.get_function_gradients(field, face_gradients);
      for (const unsigned q : face_values.quadrature_point_indices()) {
        const Point<dim>& x = face_values.quadrature_point(q);
        boundary_sum +=
            boundary.integrand(s(x) * face_gradients[q].norm()) * rho(x) * face_values.JxW(q);
      }
    }
  }
  Utilities::MPI::sum(ArrayView<const double>(sums), communicator_, ArrayView<double>(sums));
  return {.flow = flow * weights_.measure_factor,
          .dissipation = dissipation * weights_.measure_factor,
          .yielded_fraction = volume > 0.0 ? yielded / volume : 0.0,
          .boundary = boundary_sum * weights_.measure_factor,
          .max_value = solution_.linfty_norm()};
}

template <int dim>
void ScalarFlowSolver<dim>::Implementation::refine_mesh() {
  const VectorType& field = system_.readable(solution_);
  Vector<float> indicators(triangulation_->n_active_cells());
  KellyErrorEstimator<dim>::estimate(mapping_, dof_handler_, QGauss<dim - 1>(fe_.degree + 1),
                                     std::map<types::boundary_id, const Function<dim>*>(), field,
                                     indicators);
  // The top fraction of the cells of all ranks.
  if constexpr (dim == 1) {
    GridRefinement::refine_and_coarsen_fixed_number(*triangulation_, indicators,
                                                    settings_.refine_fraction, 0.0);
  } else {
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        *triangulation_, indicators, settings_.refine_fraction, 0.0);
  }

  // Cells a yield surface crosses: some quadrature points above τ_y, some below.
  const QGauss<dim> quadrature(fe_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature, update_gradients | update_quadrature_points);
  std::vector<Tensor<1, dim>> gradients(quadrature.size());
  std::size_t k = 0;
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(field, gradients);
    bool above = false, below = false;
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      (local_state(fe_values.quadrature_point(q), gradients[q], k).yielded ? above : below) = true;
      ++k;
    }
    if (above && below && law_->yield_stress() > 0.0) cell->set_refine_flag();
  }

  refine_and_transfer(*triangulation_, dof_handler_, field, solution_,
                      [this] { return setup_system(); });
  impose_boundary_values();
}

// One operating point, in the manner of the deal.II tutorials: the base mesh,
// a first solve, then cycles of refinement and solves on the refined mesh.
template <int dim>
PointResult ScalarFlowSolver<dim>::Implementation::run(const Drive& drive,
                                                       const BoundaryFunctional& boundary) {
  const auto start = std::chrono::steady_clock::now();
  drive_ = drive;
  const bool warm = setup_base_mesh();
  PointResult result;
  Outputs before;  // at 10ε (regularised) or earlier in the ALG2 iterations
  result.iterations += solve(warm, boundary, before);
  previous_base_solution_ = solution_;
  previous_rate_ = drive.characteristic_rate;
  Outputs value = evaluate(boundary);
  result.regularisation_error = regularisation_error(value, before);

  for (unsigned cycle = 0; cycle < settings_.adaptive_cycles; ++cycle) {
    refine_mesh();
    const Outputs coarse_value = value;
    result.iterations += solve_after_refinement();
    value = evaluate(boundary);
    result.discretisation_error = difference(value, coarse_value, 1.0);
  }
  result.value = value;
  result.cells = triangulation_->n_global_active_cells();
  result.dofs = dof_handler_.n_dofs();
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// One VTU file however many ranks share the mesh (MPI-IO); every rank of the
// mesh's communicator calls this with the same file name.
template <int dim>
void ScalarFlowSolver<dim>::Implementation::output_results(
    const std::filesystem::path& file) const {
  // A 1D section is solved whole on every rank of its group: one writes it.
  if (dim == 1 && Utilities::MPI::this_mpi_process(settings_.mesh_communicator) != 0) return;
  // Cell averages of the derived fields (one value per cell keeps the file
  // small and shows the yield surface as the set of partly yielded cells).
  const VectorType& field = system_.readable(solution_);
  const unsigned n_cells = triangulation_->n_active_cells();
  Vector<double> rate(n_cells), tau(n_cells), eta(n_cells), yielded(n_cells);
  const QGauss<dim> quadrature(fe_.degree + 1);
  FEValues<dim> fe_values(mapping_, fe_, quadrature, update_gradients | update_quadrature_points);
  std::vector<Tensor<1, dim>> gradients(quadrature.size());
  std::size_t k = 0;
  for (const auto& cell : owned_cells(dof_handler_)) {
    fe_values.reinit(cell);
    fe_values.get_function_gradients(field, gradients);
    const unsigned c = cell->active_cell_index();
    for (const unsigned q : fe_values.quadrature_point_indices()) {
      const LocalState local = local_state(fe_values.quadrature_point(q), gradients[q], k);
      rate(c) += local.rate / quadrature.size();
      tau(c) += local.stress / quadrature.size();
      yielded(c) += local.yielded ? 1.0 / quadrature.size() : 0.0;
      ++k;
    }
    eta(c) = rate(c) > 0.0 ? tau(c) / rate(c) : std::numeric_limits<double>::infinity();
  }
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler_);
  data_out.add_data_vector(field,
                           weights_.rate_radius_power == 1 ? "angular_velocity" : "velocity");
  data_out.add_data_vector(rate, "shear_rate");
  data_out.add_data_vector(tau, "stress");
  data_out.add_data_vector(eta, "viscosity");
  data_out.add_data_vector(yielded, "yielded");
  data_out.build_patches(mapping_, fe_.degree);
  io::write_vtu(data_out, file, communicator_);
}

// --- the public face -------------------------------------------------------------

template <int dim>
ScalarFlowSolver<dim>::ScalarFlowSolver(const Triangulation<dim>& base_mesh,
                                        unsigned mapping_degree, const SectionWeights& weights,
                                        std::shared_ptr<const ShearLaw> law,
                                        const WallSlip& slip, const SolverSettings& settings)
    : impl_(std::make_unique<Implementation>(base_mesh, mapping_degree, weights, std::move(law),
                                             slip, settings)) {}

template <int dim>
ScalarFlowSolver<dim>::~ScalarFlowSolver() = default;

template <int dim>
PointResult ScalarFlowSolver<dim>::run(const Drive& drive, const BoundaryFunctional& boundary) {
  return impl_->run(drive, boundary);
}

template <int dim>
void ScalarFlowSolver<dim>::output_results(const std::filesystem::path& file) const {
  impl_->output_results(file);
}

template class ScalarFlowSolver<1>;
template class ScalarFlowSolver<2>;

}  // namespace softglass::macro::fe
