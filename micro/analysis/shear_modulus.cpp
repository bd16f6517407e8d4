#include "micro/analysis/shear_modulus.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <vector>

namespace softglass::micro {

ShearModulus shear_modulus(ContactSystem& system, double tolerance) {
  const ContactList& c = system.compute_forces({.contacts = true}).contacts;
  const Eigen::Index dof = 3 * static_cast<Eigen::Index>(system.size());

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * c.size());
  Eigen::VectorXd xi = Eigen::VectorXd::Zero(dof);
  double e_gg = 0.0;

  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3& d = c.separation[k];
    const double r = d.norm();
    const Vec3 n = d / r;
    const double f = c.force[k], stiff = c.stiffness[k];
    const double r_g = d.x() * d.y() / r;
    e_gg += stiff * r_g * r_g - f * d.y() * d.y() * (1.0 - n.x() * n.x()) / r;
    const Vec3 mixed = stiff * r_g * n - (f * d.y() / r) * (Vec3::UnitX() - n * n.x());
    const Eigen::Index i = 3 * c.i[k], j = 3 * c.j[k];
    xi.segment<3>(i) += mixed;
    xi.segment<3>(j) -= mixed;
    const Eigen::Matrix3d block =
        stiff * n * n.transpose() - (f / r) * (Eigen::Matrix3d::Identity() - n * n.transpose());
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        entries.emplace_back(i + a, i + b, block(a, b));
        entries.emplace_back(j + a, j + b, block(a, b));
        entries.emplace_back(i + a, j + b, -block(a, b));
        entries.emplace_back(j + a, i + b, -block(a, b));
      }
    }
  }

  Eigen::SparseMatrix<double> hessian(dof, dof);
  hessian.setFromTriplets(entries.begin(), entries.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(std::max<Eigen::Index>(10 * dof, 1000));
  cg.compute(hessian);
  const Eigen::VectorXd u = cg.solve(xi);

  const double volume = system.box().volume();
  ShearModulus result;
  result.affine_modulus = e_gg / volume;
  result.modulus = (e_gg - xi.dot(u)) / volume;
  result.iterations = static_cast<std::size_t>(cg.iterations());
  result.solver_error = cg.error();
  return result;
}

}  // namespace softglass::micro
