// Weighted nonlinear least squares, solved by Eigen's Levenberg–Marquardt
// (unsupported/Eigen/LevenbergMarquardt: MINPACK's lmder, ported to Eigen).
//
// A problem supplies its residuals r_i(p), already divided by the standard
// error of each datum so that χ² = Σ r_i², and their Jacobian J = ∂r/∂p. The
// result holds the minimum, the goodness of fit and the covariance (JᵀJ)⁻¹ at
// the minimum. That covariance is the parameters' when the standard errors are
// right and the model is close to linear across the error ellipsoid; the
// bridge uses it for checks (is the yield stress significant?) and for fits of
// measured curves, and bootstraps the simulated ones instead (sweep/bootstrap.h).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>

namespace softglass::bridge {

struct LeastSquaresProblem {
  Eigen::Index parameters = 0, residuals = 0;
  std::function<void(const Eigen::VectorXd& p, Eigen::VectorXd& r)> residual;
  std::function<void(const Eigen::VectorXd& p, Eigen::MatrixXd& jacobian)> jacobian;
};

/// χ² at the minimum, the degrees of freedom (residuals − parameters) and the
/// probability of a χ² at least this large if the model and the errors are right.
///
/// When the standard errors are themselves estimates with ν degrees of freedom
/// (and independent of the values, as the variance and the mean of Gaussian
/// samples are), χ²/dof follows Fisher's F(dof, ν) rather than χ²_dof/dof, whose
/// tail is much heavier for small ν: for dof = 8, ν = 40 the χ² test's 0.1 %
/// threshold is exceeded 0.6 % of the time. The p-value uses F then.
struct GoodnessOfFit {
  double chi2 = 0.0;
  int dof = 0;
  double p_value = std::numeric_limits<double>::quiet_NaN();
  double reduced_chi2() const {
    return dof > 0 ? chi2 / dof : std::numeric_limits<double>::quiet_NaN();
  }
};

struct LeastSquaresResult {
  Eigen::VectorXd parameters;
  Eigen::MatrixXd covariance;  // (JᵀJ)⁻¹; NaN when J is rank deficient
  GoodnessOfFit goodness;
  bool converged = false;
  std::string status;  // what the solver said, for messages
};

/// Minimises χ² from `start`. Never throws on numerical trouble: a failed
/// solve has `converged == false` and says why in `status`. `error_dof` is ν
/// above (infinite when the errors are known).
LeastSquaresResult solve_least_squares(const LeastSquaresProblem& problem, Eigen::VectorXd start,
                                       double error_dof = std::numeric_limits<double>::infinity());

/// The goodness of fit of χ² with `dof` degrees of freedom, errors with `error_dof`.
GoodnessOfFit goodness_of_fit(double chi2, int dof,
                              double error_dof = std::numeric_limits<double>::infinity());

}  // namespace softglass::bridge
