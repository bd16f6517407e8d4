#include "bridge/fit/error_model.h"

#include <Eigen/QR>
#include <cmath>

namespace softglass::bridge {

void smooth_errors(Curve& curve, const std::vector<std::size_t>& packings) {
  const auto n = static_cast<Eigen::Index>(curve.size());
  for (double y : curve.y)
    if (!(std::abs(y) > 0.0)) return;
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd log_relative(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    design(i, 0) = 1.0;
    design(i, 1) = std::log(curve.x[i]);
    log_relative(i) = std::log(curve.se[i] / std::abs(curve.y[i]));
  }
  const Eigen::Vector2d shape = design.colPivHouseholderQr().solve(log_relative);
  Eigen::VectorXd smooth(n);
  double ratio = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    smooth(i) = std::abs(curve.y[i]) * std::exp(shape(0) + shape(1) * design(i, 1));
    ratio += curve.se[i] * curve.se[i] / (smooth(i) * smooth(i));
  }
  const double level = std::sqrt(ratio / static_cast<double>(n));
  for (Eigen::Index i = 0; i < n; ++i) curve.se[i] = level * smooth(i);
  double dof = -2.0;
  for (std::size_t k : packings) dof += static_cast<double>(k) - 1.0;
  if (dof >= 1.0) curve.error_dof = dof;
}

}  // namespace softglass::bridge
