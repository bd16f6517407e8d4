#include "bridge/fit/least_squares.h"

#include <Eigen/SVD>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <unsupported/Eigen/LevenbergMarquardt>

#include <cmath>

namespace softglass::bridge {

namespace {

// Eigen's functor interface around the problem. Non-finite residuals (a trial
// step into overflow, e.g. a huge exponent) are replaced by a very large value:
// the step then shows no reduction of χ² and Levenberg–Marquardt shrinks its
// trust region instead of stopping.
struct Functor : Eigen::DenseFunctor<double> {
  explicit Functor(const LeastSquaresProblem& p)
      : Eigen::DenseFunctor<double>(static_cast<int>(p.parameters), static_cast<int>(p.residuals)),
        problem(p) {}
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    problem.residual(x, r);
    for (auto& v : r)
      if (!std::isfinite(v)) v = 1e150;
    return 0;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian) const {
    problem.jacobian(x, jacobian);
    return 0;
  }
  const LeastSquaresProblem& problem;
};

const char* describe(Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (status) {
    case ImproperInputParameters:
      return "improper input or a singular Jacobian";
    case TooManyFunctionEvaluation:
      return "no convergence within the evaluation budget";
    case UserAsked:
      return "stopped";
    default:
      return "converged";
  }
}

// (JᵀJ)⁻¹ through the singular values of J, NaN if J has (numerically) lower rank.
Eigen::MatrixXd covariance_of(const Eigen::MatrixXd& jacobian) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::Index n = jacobian.cols();
  if (s.size() < n || !s.allFinite() || s(n - 1) <= 1e-12 * s(0)) {
    return Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  }
  const Eigen::MatrixXd& v = svd.matrixV();
  return v * s.cwiseInverse().cwiseAbs2().asDiagonal() * v.transpose();
}

}  // namespace

GoodnessOfFit goodness_of_fit(double chi2, int dof, double error_dof) {
  GoodnessOfFit g;
  g.chi2 = chi2;
  g.dof = dof;
  if (dof <= 0 || !std::isfinite(chi2)) return g;
  namespace bm = boost::math;
  g.p_value = std::isfinite(error_dof)
                  ? bm::cdf(bm::complement(bm::fisher_f(dof, error_dof), chi2 / dof))
                  : bm::cdf(bm::complement(bm::chi_squared(dof), chi2));
  return g;
}

LeastSquaresResult solve_least_squares(const LeastSquaresProblem& problem, Eigen::VectorXd start,
                                       double error_dof) {
  Functor functor(problem);
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  // Tight tolerances: bootstrap standard deviations are differences of minima,
  // and must not be polluted by where the solver happened to stop.
  lm.setXtol(1e-12);
  lm.setFtol(1e-12);
  lm.setMaxfev(400 * (problem.parameters + 1));
  const auto status = lm.minimize(start);

  LeastSquaresResult result;
  result.parameters = start;
  result.status = describe(status);
  Eigen::VectorXd r(problem.residuals);
  problem.residual(start, r);
  Eigen::MatrixXd jacobian(problem.residuals, problem.parameters);
  problem.jacobian(start, jacobian);
  result.converged = status != Eigen::LevenbergMarquardtSpace::ImproperInputParameters &&
                     status != Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation &&
                     status != Eigen::LevenbergMarquardtSpace::UserAsked && r.allFinite() &&
                     start.allFinite();
  if (!r.allFinite() || !start.allFinite()) result.status = "the solution is not finite";
  result.goodness = goodness_of_fit(
      r.squaredNorm(), static_cast<int>(problem.residuals - problem.parameters), error_dof);
  result.covariance = jacobian.allFinite()
                          ? covariance_of(jacobian)
                          : Eigen::MatrixXd::Constant(problem.parameters, problem.parameters,
                                                      std::numeric_limits<double>::quiet_NaN());
  return result;
}

}  // namespace softglass::bridge
