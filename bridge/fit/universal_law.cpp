#include "bridge/fit/universal_law.h"

#include <algorithm>
#include <cmath>

#include "bridge/fit/herschel_bulkley.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

// Q_ij = a_j + k (α_j + β_j a_j) √x_ij; parameters (a_0 … a_{J−1}, k).
UniversalFit fit_collapse(const std::vector<const Curve*>& curves, const std::vector<double>& alpha,
                          const std::vector<double>& beta) {
  const auto groups = static_cast<Eigen::Index>(curves.size());
  require(groups >= 1, "a universal fit needs at least one volume fraction");
  Eigen::Index points = 0;
  for (const Curve* c : curves) points += static_cast<Eigen::Index>(c->size());

  LeastSquaresProblem problem;
  problem.parameters = groups + 1;
  problem.residuals = points;
  problem.residual = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    const double k = p(groups);
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < groups; ++j) {
      const Curve& c = *curves[j];
      const double slope = k * (alpha[j] + beta[j] * p(j));
      for (std::size_t i = 0; i < c.size(); ++i, ++row)
        r(row) = (c.y[i] - p(j) - slope * std::sqrt(c.x[i])) / c.se[i];
    }
  };
  problem.jacobian = [&](const Eigen::VectorXd& p, Eigen::MatrixXd& jac) {
    jac.setZero();
    const double k = p(groups);
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < groups; ++j) {
      const Curve& c = *curves[j];
      for (std::size_t i = 0; i < c.size(); ++i, ++row) {
        const double root = std::sqrt(c.x[i]);
        jac(row, j) = -(1.0 + k * beta[j] * root) / c.se[i];
        jac(row, groups) = -(alpha[j] + beta[j] * p(j)) * root / c.se[i];
      }
    }
  };

  // Start: each curve's own m = ½ law; k the median of the curves' own k.
  Eigen::VectorXd start(groups + 1);
  std::vector<double> own_k;
  for (Eigen::Index j = 0; j < groups; ++j) {
    const SquareRootLaw law = fit_square_root_law(*curves[j]);
    start(j) = law.intercept;
    own_k.push_back(law.slope / (alpha[j] + beta[j] * law.intercept));
  }
  std::nth_element(own_k.begin(), own_k.begin() + groups / 2, own_k.end());
  start(groups) = own_k[groups / 2];

  const LeastSquaresResult solved = solve_least_squares(problem, start);
  UniversalFit fit;
  fit.k = solved.parameters(groups);
  fit.yield.assign(solved.parameters.data(), solved.parameters.data() + groups);
  fit.goodness = solved.goodness;
  fit.converged = solved.converged;
  fit.status = solved.status;
  return fit;
}

}  // namespace

UniversalFit fit_universal_stress(const std::vector<const Curve*>& curves,
                                  const std::vector<double>& modulus) {
  return fit_collapse(curves, modulus, std::vector<double>(curves.size(), 0.0));
}

UniversalFit fit_universal_normal(const std::vector<const Curve*>& curves,
                                  const std::vector<double>& yield_strain) {
  std::vector<double> beta;
  for (double g : yield_strain) beta.push_back(1.0 / g);
  return fit_collapse(curves, std::vector<double>(curves.size(), 0.0), beta);
}

}  // namespace softglass::bridge
