#include "bridge/fit/universal_law.h"

#include <algorithm>
#include <cmath>

#include "bridge/fit/herschel_bulkley.h"
#include "common/errors.h"

namespace softglass::bridge {

// Q_ij = a_j + k α_j √x_ij with α_j = sign G0_j; parameters (a_0 … a_{J−1}, k).
// Linear, so Levenberg–Marquardt ends in a step or two from any start; it is
// used for its goodness of fit and covariance, shared with the other fits.
UniversalFit fit_universal_law(const std::vector<const Curve*>& curves,
                               const std::vector<double>& modulus, double sign) {
  const auto groups = static_cast<Eigen::Index>(curves.size());
  require(groups >= 1, "a universal fit needs at least one volume fraction");
  require(modulus.size() == curves.size(), "a universal fit needs one G0 per volume fraction");
  require(sign == 1.0 || sign == -1.0, "a universal law's sign is +1 or -1");
  Eigen::Index points = 0;
  for (const Curve* c : curves) points += static_cast<Eigen::Index>(c->size());
  std::vector<double> alpha;
  for (double g : modulus) alpha.push_back(sign * g);

  LeastSquaresProblem problem;
  problem.parameters = groups + 1;
  problem.residuals = points;
  problem.residual = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    const double k = p(groups);
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < groups; ++j) {
      const Curve& c = *curves[j];
      for (std::size_t i = 0; i < c.size(); ++i, ++row)
        r(row) = (c.y[i] - p(j) - k * alpha[j] * std::sqrt(c.x[i])) / c.se[i];
    }
  };
  problem.jacobian = [&](const Eigen::VectorXd&, Eigen::MatrixXd& jac) {
    jac.setZero();
    Eigen::Index row = 0;
    for (Eigen::Index j = 0; j < groups; ++j) {
      const Curve& c = *curves[j];
      for (std::size_t i = 0; i < c.size(); ++i, ++row) {
        jac(row, j) = -1.0 / c.se[i];
        jac(row, groups) = -alpha[j] * std::sqrt(c.x[i]) / c.se[i];
      }
    }
  };

  // Start: each curve's own m = ½ law; k the median of the curves' own k.
  Eigen::VectorXd start(groups + 1);
  std::vector<double> own_k;
  for (Eigen::Index j = 0; j < groups; ++j) {
    const SquareRootLaw law = fit_square_root_law(*curves[j]);
    start(j) = law.intercept;
    own_k.push_back(law.slope / alpha[j]);
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

}  // namespace softglass::bridge
