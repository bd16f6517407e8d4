// The finite-element solver of sphere_compression.h, written as deal.II's
// tutorial programs are: make_grid / setup_system / assemble / solve, and
// compress_to() as the run of the loading.
#include "macro/particle/sphere_compression.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::macro::particle {

using namespace dealii;

void SphereCompressionSettings::validate() const {
  require(global_refinements >= 1 && global_refinements <= 7,
          fmt::format("sphere compression: global refinements = {} is not allowed; allowed: 1 to 7",
                      global_refinements));
  require(pole_refinements <= 12,
          fmt::format("sphere compression: pole refinements = {} is not allowed; allowed: 0 to 12",
                      pole_refinements));
  require(
      poisson_ratio >= 0.0 && poisson_ratio <= 0.4999,
      fmt::format("sphere compression: Poisson's ratio = {} is not allowed; allowed: 0 to 0.4999",
                  poisson_ratio));
  require(
      std::isfinite(penalty) && penalty > 0.0,
      fmt::format("sphere compression: penalty = {} is not allowed; allowed: a finite number > 0",
                  penalty));
  require(
      newton_tolerance > 0.0 && newton_tolerance < 1.0,
      fmt::format("sphere compression: Newton tolerance = {} is not allowed; allowed: 0 < tol < 1",
                  newton_tolerance));
  require(max_newton_iterations >= 1, "sphere compression: at least one Newton iteration");
}

namespace {
// Boundary indicators of the meridian quarter disc.
constexpr types::boundary_id kSurface = 0;  // the sphere's free (or contacting) surface
constexpr types::boundary_id kAxis = 1;     // r = 0
constexpr types::boundary_id kEquator = 2;  // z = 0, the plane of symmetry

}  // namespace

class SphereCompression::Solver {
 public:
  explicit Solver(const SphereCompressionSettings& s)
      : settings_(s),
        shear_modulus_(1.0 - s.poisson_ratio),  // μ = E*(1 − ν), E* = 1
        bulk_modulus_(2.0 * shear_modulus_ * (1.0 + s.poisson_ratio) /
                      (3.0 * (1.0 - 2.0 * s.poisson_ratio))),
        fe_(FE_Q<2>(2), 2),
        mapping_(2),
        dof_handler_(triangulation_) {
    make_grid();
    setup_system();
  }

  CompressionState compress_to(double indentation);
  double indentation() const { return indentation_; }
  unsigned int n_dofs() const { return dof_handler_.n_dofs(); }
  unsigned int n_cells() const { return triangulation_.n_active_cells(); }

 private:
  struct Assembled {
    double energy = 0.0, force = 0.0, contact_radius = 0.0, volume_change = 0.0;
    bool invertible = true;  // J > 0 at every quadrature point
  };
  void make_grid();
  void setup_system();
  Assembled assemble(double indentation, bool with_system);
  void solve();
  CompressionState equilibrate(double indentation);

  const SphereCompressionSettings settings_;
  const double shear_modulus_, bulk_modulus_;
  Triangulation<2> triangulation_;
  const FESystem<2> fe_;
  const MappingQ<2> mapping_;  // quadratic: the pole's curvature is what Hertz's law sees
  DoFHandler<2> dof_handler_;
  AffineConstraints<double> constraints_;
  SparsityPattern sparsity_pattern_;
  SparseMatrix<double> tangent_;
  Vector<double> solution_, residual_, update_;
  double indentation_ = 0.0;  // of the equilibrium in solution_
  // The equilibrium before it, for the secant predictor (none at first).
  Vector<double> previous_solution_;
  double previous_indentation_ = -1.0;
};

// The quarter disc r, z ≥ 0, r² + z² ≤ 1 (R = 1), refined uniformly and then
// towards the pole r = 0, z = 1 where the plate touches: a cell is refined
// while the pole is within a few of its diameters, so that cell sizes grow
// geometrically away from the contact.
void SphereCompression::Solver::make_grid() {
  GridGenerator::quarter_hyper_ball(triangulation_, Point<2>(), 1.0);
  for (const auto& cell : triangulation_.active_cell_iterators())
    for (const auto& face : cell->face_iterators())
      if (face->at_boundary()) {
        const Point<2> c = face->center();
        face->set_boundary_id(c[0] < 1e-12 ? kAxis : c[1] < 1e-12 ? kEquator : kSurface);
      }
  triangulation_.refine_global(settings_.global_refinements);
  const Point<2> pole(0.0, 1.0);
  for (unsigned int k = 0; k < settings_.pole_refinements; ++k) {
    for (const auto& cell : triangulation_.active_cell_iterators())
      if (cell->center().distance(pole) < 3.0 * cell->diameter()) cell->set_refine_flag();
    triangulation_.execute_coarsening_and_refinement();
  }
}

// Displacement (u_r, u_z) in Q2; the axis holds u_r = 0 and the
// equator u_z = 0, both homogeneous, so every Newton update keeps them.
void SphereCompression::Solver::setup_system() {
  dof_handler_.distribute_dofs(fe_);
  constraints_.clear();
  DoFTools::make_hanging_node_constraints(dof_handler_, constraints_);
  const FEValuesExtractors::Scalar radial(0), axial(1);
  VectorTools::interpolate_boundary_values(mapping_, dof_handler_, kAxis,
                                           Functions::ZeroFunction<2>(2), constraints_,
                                           fe_.component_mask(radial));
  VectorTools::interpolate_boundary_values(mapping_, dof_handler_, kEquator,
                                           Functions::ZeroFunction<2>(2), constraints_,
                                           fe_.component_mask(axial));
  constraints_.close();

  DynamicSparsityPattern dsp(dof_handler_.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
  sparsity_pattern_.copy_from(dsp);
  tangent_.reinit(sparsity_pattern_);
  solution_.reinit(dof_handler_.n_dofs());
  residual_.reinit(dof_handler_.n_dofs());
  update_.reinit(dof_handler_.n_dofs());
}

namespace {

double value(double x) {
  return x;
}
template <typename Number>
double value(const Number& x) {
  return Differentiation::AD::ADNumberTraits<Number>::get_scalar_value(x);
}

// One cell's part of Π and of the state report.
template <typename Number>
struct CellEnergy {
  Number energy = 0.0;
  double force = 0.0, contact_radius = 0.0, volume_change = 0.0;
  bool invertible = true;  // J > 0 at every quadrature point
};

// Π of one cell as a function of its degrees of freedom U — in doubles for
// the line search, in AD numbers for the Newton system (one expression, so
// the two cannot disagree). fe_values must be reinitialised on the cell.
template <typename Number>
CellEnergy<Number> cell_energy(const std::vector<Number>& U,
                               const DoFHandler<2>::active_cell_iterator& cell,
                               const FEValues<2>& fe_values, FEFaceValues<2>& fe_face_values,
                               double mu, double kappa, double k, double plate) {
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int n_q = fe_values.n_quadrature_points;
  std::vector<Tensor<2, 2, Number>> grad_u(n_q);
  std::vector<Tensor<1, 2, Number>> u(n_q), u_face(fe_face_values.n_quadrature_points);
  fe_values[displacement].get_function_gradients_from_local_dof_values(U, grad_u);
  fe_values[displacement].get_function_values_from_local_dof_values(U, u);

  // The deviatoric energy at the quadrature points; the volumetric one of
  // the cell's mean dilatation J̄ = ∫J dV / ∫dV.
  CellEnergy<Number> c;
  Number volume_now = 0.0;
  double volume = 0.0;
  for (unsigned int q = 0; q < n_q; ++q) {
    const double r = fe_values.quadrature_point(q)[0];
    const double dV = 2.0 * numbers::PI * r * fe_values.JxW(q);
    // F in cylindrical components: the meridian block and the hoop stretch.
    const Number f_rr = 1.0 + grad_u[q][0][0], f_rz = grad_u[q][0][1];
    const Number f_zr = grad_u[q][1][0], f_zz = 1.0 + grad_u[q][1][1];
    const Number f_tt = 1.0 + u[q][0] / r;
    const Number J = f_tt * (f_rr * f_zz - f_rz * f_zr);
    if (!(value(J) > 0.0)) {
      c.invertible = false;
      return c;
    }
    const Number I1 = f_rr * f_rr + f_rz * f_rz + f_zr * f_zr + f_zz * f_zz + f_tt * f_tt;
    c.energy += 0.5 * mu * (std::pow(J, -2.0 / 3.0) * I1 - 3.0) * dV;
    volume_now += J * dV;
    volume += dV;
  }
  const Number mean_dilatation = volume_now / volume;
  c.energy += 0.5 * kappa * (mean_dilatation - 1.0) * (mean_dilatation - 1.0) * volume;
  c.volume_change = std::abs(value(mean_dilatation) - 1.0);

  // The plate: a penalty on the reference surface points above it.
  for (const auto& face : cell->face_iterators()) {
    if (!face->at_boundary() || face->boundary_id() != kSurface) continue;
    fe_face_values.reinit(cell, face);
    fe_face_values[displacement].get_function_values_from_local_dof_values(U, u_face);
    for (unsigned int q = 0; q < u_face.size(); ++q) {
      const Point<2>& x = fe_face_values.quadrature_point(q);
      const Number gap = x[1] + u_face[q][1] - plate;
      if (value(gap) <= 0.0) continue;
      const double area = 2.0 * numbers::PI * x[0] * fe_face_values.JxW(q);
      c.energy += 0.5 * k * gap * gap * area;
      c.force += k * value(gap) * area;
      c.contact_radius = std::max(c.contact_radius, x[0] + value(u_face[q][0]));
    }
  }
  return c;
}

}  // namespace

// Π and the state report at the present solution, with (`with_system`) or
// without the Newton system: gradient ∂Π/∂U and Hessian ∂²Π/∂U² of each
// cell from Sacado's forward-over-forward derivatives (the system's
// right-hand side is −∂Π/∂U).
SphereCompression::Solver::Assembled SphereCompression::Solver::assemble(double indentation,
                                                                         bool with_system) {
  using ADHelper =
      Differentiation::AD::EnergyFunctional<Differentiation::AD::NumberTypes::sacado_dfad_dfad,
                                            double>;
  using ADNumber = typename ADHelper::ad_type;
  const QGauss<2> quadrature(3);
  const QGauss<1> face_quadrature(3);
  FEValues<2> fe_values(
      mapping_, fe_, quadrature,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  FEFaceValues<2> fe_face_values(mapping_, fe_, face_quadrature,
                                 update_values | update_quadrature_points | update_JxW_values);
  const unsigned int n_dofs = fe_.n_dofs_per_cell();
  std::vector<types::global_dof_index> dof_indices(n_dofs);
  std::vector<double> local(n_dofs);
  FullMatrix<double> cell_matrix(n_dofs, n_dofs);
  Vector<double> cell_rhs(n_dofs);
  const double mu = shear_modulus_, kappa = bulk_modulus_, k = settings_.penalty;
  const double plate = 1.0 - indentation;  // the plate's height z

  if (with_system) {
    tangent_ = 0.0;
    residual_ = 0.0;
  }
  Assembled a;
  const auto add = [&a](const auto& c) {
    a.energy += value(c.energy);
    a.force += c.force;
    a.contact_radius = std::max(a.contact_radius, c.contact_radius);
    a.volume_change = std::max(a.volume_change, c.volume_change);
  };
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fe_values.reinit(cell);
    cell->get_dof_indices(dof_indices);
    if (!with_system) {
      for (unsigned int i = 0; i < n_dofs; ++i) local[i] = solution_[dof_indices[i]];
      const CellEnergy<double> c =
          cell_energy(local, cell, fe_values, fe_face_values, mu, kappa, k, plate);
      if (!c.invertible) return {0.0, 0.0, 0.0, 0.0, false};
      add(c);
      continue;
    }
    ADHelper ad(n_dofs);
    ad.register_dof_values(solution_, dof_indices);
    const CellEnergy<ADNumber> c = cell_energy(ad.get_sensitive_dof_values(), cell, fe_values,
                                               fe_face_values, mu, kappa, k, plate);
    if (!c.invertible) return {0.0, 0.0, 0.0, 0.0, false};
    add(c);
    ad.register_energy_functional(c.energy);
    ad.compute_residual(cell_rhs);
    cell_rhs *= -1.0;
    ad.compute_linearization(cell_matrix);
    constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dof_indices, tangent_,
                                            residual_);
  }
  return a;
}

// The Newton system: the Hessian of Π, symmetric; a sparse LU (UMFPACK)
// solves it (the 2D problem has at most some 10⁵ unknowns). Far from
// equilibrium the Hessian of the neo-Hookean energy can be indefinite (it is
// polyconvex, not convex); a direction that does not descend is solved
// again with the diagonal raised by a growing fraction of itself
// (Levenberg–Marquardt), which tends to steepest descent.
void SphereCompression::Solver::solve() {
  Vector<double> diagonal(tangent_.m());
  for (unsigned int i = 0; i < tangent_.m(); ++i) diagonal[i] = std::abs(tangent_.diag_element(i));
  double shift = 0.0;
  for (;;) {
    SparseDirectUMFPACK lu;
    lu.initialize(tangent_);
    lu.vmult(update_, residual_);
    constraints_.distribute(update_);
    if (residual_ * update_ > 0.0 || shift >= 1e6) return;
    const double next = shift == 0.0 ? 1e-4 : 10.0 * shift;
    for (unsigned int i = 0; i < tangent_.m(); ++i)
      tangent_.diag_element(i) += (next - shift) * diagonal[i];
    shift = next;
  }
}

// The plate is advanced in steps that grow geometrically (by at most a
// quarter) from δ₀ = 1e-4 R, where the undeformed sphere is a good enough
// first guess; every later step starts from the secant predictor through the
// last two equilibria. A step that fails is retried at half its length.
CompressionState SphereCompression::Solver::compress_to(double indentation) {
  constexpr double kFirst = 1e-4, kGrowth = 1.25;
  CompressionState state;
  double growth = kGrowth;
  while (indentation_ < indentation) {
    const double next = indentation_ == 0.0 ? std::min(indentation, kFirst)
                                            : std::min(indentation, indentation_ * growth);
    try {
      state = equilibrate(next);
      growth = std::min(kGrowth, 1.0 + 2.0 * (growth - 1.0));
    } catch (const NumericalError&) {
      if (growth < 1.0 + 1e-3) throw;
      growth = 1.0 + 0.5 * (growth - 1.0);
    }
  }
  return state;
}

// Newton from the predictor to the equilibrium at δ, with a backtracking line
// search on Π (Armijo; Nocedal & Wright ch. 3): Π is the potential energy of
// an elastic body and a convex penalty, so it is a merit function and a step
// that would invert an element counts as an increase. On success the
// equilibrium is the solver's state; on failure the state is unchanged.
CompressionState SphereCompression::Solver::equilibrate(double indentation) {
  const Vector<double> start = solution_;
  const auto fail = [&](const std::string& why) {
    solution_ = start;
    return NumericalError(
        fmt::format("sphere compression: at indentation {}: {}", indentation, why));
  };
  if (previous_indentation_ >= 0.0) {
    const double ratio = (indentation - indentation_) / (indentation_ - previous_indentation_);
    solution_.sadd(1.0 + ratio, -ratio, previous_solution_);
  }
  CompressionState state;
  state.indentation = indentation;
  Assembled a = assemble(indentation, true);
  if (!a.invertible) {
    solution_ = start;  // the predictor overshot: from the last equilibrium
    a = assemble(indentation, true);
    if (!a.invertible) throw fail("an element is inverted");
  }
  for (unsigned int it = 1; it <= settings_.max_newton_iterations; ++it) {
    solve();
    state.newton_iterations = it;
    const double correction = update_.linfty_norm();
    // Converged when the correction moves no point by more than tolerance × R:
    // it is applied in full, leaving an error of its square (quadratic
    // convergence), below what the energy can resolve in a line search.
    if (correction <= settings_.newton_tolerance) {
      solution_ += update_;
      a = assemble(indentation, false);
      previous_solution_ = start;
      previous_indentation_ = indentation_;
      indentation_ = indentation;
      state.force = a.force;
      state.energy = a.energy;
      state.contact_radius = a.contact_radius;
      state.volume_change = a.volume_change;
      return state;
    }
    const double slope = -(residual_ * update_);  // ∂Π/∂U · ΔU < 0 for a descent direction
    if (!(slope < 0.0)) throw fail("the Newton direction is not a descent direction");
    const Vector<double> before = solution_;
    const double energy = a.energy;
    double step = 1.0;
    for (;;) {
      solution_ = before;
      solution_.add(step, update_);
      a = assemble(indentation, false);
      if (a.invertible && a.energy <= energy + 1e-4 * step * slope) break;
      step *= 0.5;
      if (step < 1e-6) throw fail("the line search found no decrease of the energy");
    }
    a = assemble(indentation, true);
  }
  throw fail(
      fmt::format("Newton did not converge in {} iterations", settings_.max_newton_iterations));
}

SphereCompression::SphereCompression(const SphereCompressionSettings& settings) {
  settings.validate();
  solver_ = std::make_unique<Solver>(settings);
}
SphereCompression::~SphereCompression() = default;

CompressionState SphereCompression::compress_to(double indentation) {
  require(std::isfinite(indentation) && indentation > 0.0 && indentation < 0.5,
          fmt::format("sphere compression: indentation {} is not allowed; allowed: 0 < δ/R < 1/2",
                      indentation));
  require(indentation > solver_->indentation(),
          fmt::format("sphere compression: indentation {} is not beyond the present {}; the "
                      "sphere is only loaded",
                      indentation, solver_->indentation()));
  return solver_->compress_to(indentation);
}
unsigned int SphereCompression::n_dofs() const {
  return solver_->n_dofs();
}
unsigned int SphereCompression::n_cells() const {
  return solver_->n_cells();
}

}  // namespace softglass::macro::particle
