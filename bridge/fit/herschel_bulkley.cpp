#include "bridge/fit/herschel_bulkley.h"

#include <fmt/format.h>

#include <Eigen/QR>
#include <cmath>

#include "common/errors.h"

namespace softglass::bridge {

double HbParameters::operator()(double x) const {
  return yield + consistency * std::pow(x, exponent);
}

SquareRootLaw fit_square_root_law(const Curve& curve) {
  const auto n = static_cast<Eigen::Index>(curve.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0 / curve.se[i];
    a(i, 1) = std::sqrt(curve.x[i]) / curve.se[i];
    b(i) = curve.y[i] / curve.se[i];
  }
  const Eigen::Vector2d p = a.colPivHouseholderQr().solve(b);
  return {p(0), p(1)};
}

HerschelBulkleyFit fit_herschel_bulkley(const Curve& curve) {
  const auto n = static_cast<Eigen::Index>(curve.size());
  if (n < 4) {
    throw InputError(
        fmt::format("a Herschel-Bulkley fit needs at least 4 rates (3 parameters and one degree of "
                    "freedom); this curve has {}",
                    n));
  }
  double log_sum = 0.0;
  for (double x : curve.x) log_sum += std::log(x);
  const double x_ref = std::exp(log_sum / static_cast<double>(n));
  Eigen::VectorXd log_t(n);
  for (Eigen::Index i = 0; i < n; ++i) log_t(i) = std::log(curve.x[i] / x_ref);

  // p = (y_y, c, m): model y_y + c exp(m ln t).
  LeastSquaresProblem problem;
  problem.parameters = 3;
  problem.residuals = n;
  problem.residual = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    for (Eigen::Index i = 0; i < n; ++i)
      r(i) = (curve.y[i] - p(0) - p(1) * std::exp(p(2) * log_t(i))) / curve.se[i];
  };
  problem.jacobian = [&](const Eigen::VectorXd& p, Eigen::MatrixXd& jac) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const double power = std::exp(p(2) * log_t(i));
      jac(i, 0) = -1.0 / curve.se[i];
      jac(i, 1) = -power / curve.se[i];
      jac(i, 2) = -p(1) * power * log_t(i) / curve.se[i];
    }
  };
  const SquareRootLaw start = fit_square_root_law(curve);
  const LeastSquaresResult solved = solve_least_squares(
      problem, Eigen::Vector3d(start.intercept, start.slope * std::sqrt(x_ref), 0.5),
      curve.error_dof);

  HerschelBulkleyFit fit;
  const Eigen::VectorXd& p = solved.parameters;
  const double scale = std::pow(x_ref, -p(2));
  fit.parameters = {p(0), p(1) * scale, p(2)};
  // k = c x_ref^(−m): ∂k/∂c = x_ref^(−m), ∂k/∂m = −k ln x_ref.
  Eigen::Matrix3d to_consistency = Eigen::Matrix3d::Identity();
  to_consistency(1, 1) = scale;
  to_consistency(1, 2) = -fit.parameters.consistency * std::log(x_ref);
  fit.covariance = to_consistency * solved.covariance * to_consistency.transpose();
  fit.goodness = solved.goodness;
  fit.converged = solved.converged && p(2) > 0.0 && p(2) <= 2.0;
  fit.status = solved.converged && !fit.converged
                   ? fmt::format("exponent {:.3g} outside (0, 2]", p(2))
                   : solved.status;
  return fit;
}

PlateauCheck check_plateau(const Curve& curve, const HerschelBulkleyFit& fit) {
  const HbParameters& hb = fit.parameters;
  const double error = std::sqrt(fit.covariance(0, 0));
  const double lowest = hb(curve.x.front());
  if (!(hb.yield * lowest > 0.0) || !(std::abs(hb.yield) > 2.0 * error)) {
    return {false, fmt::format("the fitted yield value {:.4g} ± {:.2g} is not significantly "
                               "different from zero: the data show no yield plateau",
                               hb.yield, error)};
  }
  if (std::abs(hb.yield) < 0.5 * std::abs(lowest)) {
    return {false, fmt::format("the fitted yield value {:.4g} is only {:.0f} % of the value at "
                               "the lowest rate {:.3g}: the curve has not reached its yield "
                               "plateau (add lower rates)",
                               hb.yield, 100.0 * hb.yield / lowest, curve.x.front())};
  }
  return {};
}

}  // namespace softglass::bridge
