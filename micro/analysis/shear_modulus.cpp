#include "micro/analysis/shear_modulus.h"

#include <fmt/format.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.h"

namespace softglass::micro {

namespace {

// The Hessian H (sparse, symmetric) of the elastic energy in the positions.
Eigen::SparseMatrix<double> hessian(const ContactList& c, Eigen::Index dof) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3& d = c.separation[k];
    const double r = d.norm();
    const Vec3 n = d / r;
    const Eigen::Matrix3d block =
        c.stiffness[k] * n * n.transpose() -
        (c.force[k] / r) * (Eigen::Matrix3d::Identity() - n * n.transpose());
    const Eigen::Index i = 3 * c.i[k], j = 3 * c.j[k];
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        entries.emplace_back(i + a, i + b, block(a, b));
        entries.emplace_back(j + a, j + b, block(a, b));
        entries.emplace_back(i + a, j + b, -block(a, b));
        entries.emplace_back(j + a, i + b, -block(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> h(dof, dof);
  h.setFromTriplets(entries.begin(), entries.end());
  return h;
}

}  // namespace

ShearModulus shear_modulus(ContactSystem& system, double tolerance) {
  const ContactList& c = system.compute_forces({.contacts = true}).contacts;
  const Eigen::Index dof = 3 * static_cast<Eigen::Index>(system.size());
  const double volume = system.box().volume();

  const Eigen::SparseMatrix<double> h = hessian(c, dof);  // the solver keeps a reference
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(std::max<Eigen::Index>(10 * dof, 1000));
  cg.compute(h);

  ShearModulus result;
  for (std::size_t m = 0; m < kSimpleShears.size(); ++m) {
    const auto [flow, gradient] = kSimpleShears[m];
    // Simple shear x_flow += γ x_gradient; r_γ = d_flow d_gradient / r (header).
    Eigen::VectorXd xi = Eigen::VectorXd::Zero(dof);
    double e_gg = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const Vec3& d = c.separation[k];
      const double r = d.norm();
      const Vec3 n = d / r;
      const double f = c.force[k], stiff = c.stiffness[k];
      const double dg = d(gradient);
      const double r_g = d(flow) * dg / r;
      e_gg += stiff * r_g * r_g - f * dg * dg * (1.0 - n(flow) * n(flow)) / r;
      const Vec3 mixed = stiff * r_g * n - (f * dg / r) * (Vec3::Unit(flow) - n * n(flow));
      xi.segment<3>(3 * c.i[k]) += mixed;
      xi.segment<3>(3 * c.j[k]) -= mixed;
    }
    const Eigen::VectorXd u = cg.solve(xi);
    result.directions[m] = (e_gg - xi.dot(u)) / volume;
    result.affine_directions[m] = e_gg / volume;
    result.iterations += static_cast<std::size_t>(cg.iterations());
    result.solver_error = std::max(result.solver_error, cg.error());
  }
  double sum = 0.0, sum2 = 0.0, affine = 0.0;
  for (std::size_t m = 0; m < kSimpleShears.size(); ++m) {
    sum += result.directions[m], sum2 += result.directions[m] * result.directions[m];
    affine += result.affine_directions[m];
  }
  const double count = static_cast<double>(kSimpleShears.size());
  result.modulus = sum / count;
  result.affine_modulus = affine / count;
  result.flow_gradient_modulus = result.directions[0];
  result.direction_spread =
      std::sqrt(std::max(0.0, sum2 / count - result.modulus * result.modulus));
  return result;
}

void require_solid(const ShearModulus& modulus, const std::string& packing) {
  const double g = modulus.modulus, spread = modulus.direction_spread;
  if (std::isfinite(g) && g > 0 && spread < g) return;
  const auto [lo, hi] = std::minmax_element(modulus.directions.begin(), modulus.directions.end());
  throw NumericalError(fmt::format(
      "{} is not a stable solid: its shear modulus G0 = {:.3e} E* {} (six simple shears "
      "{:.3e} … {:.3e}, sd {:.2e}); a packing that is not at a stable minimum, or too small "
      "to be isotropic, cannot be sheared into a flow curve: choose another seed or more "
      "particles",
      packing, g, g > 0 ? "is below the scatter of its six shears" : "is not positive", *lo, *hi,
      spread));
}

}  // namespace softglass::micro
