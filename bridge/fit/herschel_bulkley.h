// The Herschel–Bulkley law y = y_y + k x^m fitted to one flow curve.
//
// For the simulations y = σ/E* (or N1/E*, N2/E*, f_m/E*R²) and x = γ̃ (the
// paper's σ/E* = σ_y/E* + k_σ γ̃^m); for measured curves y = τ in Pa and
// x = γ̇ in 1/s. Same mathematics, weighted by the standard errors.
//
// Parametrisation. Internally the model is y_y + c (x/x_ref)^m with x_ref the
// geometric mean of the rates: near the middle of the data the amplitude c and
// the exponent m are nearly uncorrelated, which keeps Levenberg–Marquardt well
// conditioned over rate ranges of 5 decades and more. The reported consistency
// is k = c x_ref^(−m), the value at x = 1, with the covariance transformed
// accordingly. The solve starts from the m = ½ law, which is linear.
#pragma once

#include <Eigen/Core>
#include <string>

#include "bridge/fit/curve.h"
#include "bridge/fit/least_squares.h"

namespace softglass::bridge {

struct HbParameters {
  double yield = 0.0, consistency = 0.0, exponent = 0.0;
  double operator()(double x) const;
};

struct HerschelBulkleyFit {
  HbParameters parameters;
  Eigen::Matrix3d covariance;  // of (yield, consistency, exponent), from the Jacobian
  GoodnessOfFit goodness;
  bool converged = false;  // false also when the exponent leaves (0, 2]
  std::string status;
};

/// Needs at least 4 points (3 parameters, 1 degree of freedom); InputError otherwise.
HerschelBulkleyFit fit_herschel_bulkley(const Curve& curve);

/// The law with m = ½, y = a + c √x, by linear weighted least squares.
struct SquareRootLaw {
  double intercept = 0.0, slope = 0.0;
};
SquareRootLaw fit_square_root_law(const Curve& curve);

/// Whether the curve reaches its yield plateau, judged on the fit:
///  1. the yield value has the sign of the data and lies more than two standard
///     errors from zero (within two, the data are compatible with a fluid that
///     has no yield stress: a two-sided 95 % test), and
///  2. it makes up at least half of the fitted value at the lowest rate (below
///     that the yield value is an extrapolation of the power law over rates
///     that were not measured, and depends on the assumed form).
struct PlateauCheck {
  bool ok = true;
  std::string reason;  // why not
};
PlateauCheck check_plateau(const Curve& curve, const HerschelBulkleyFit& fit);

}  // namespace softglass::bridge
