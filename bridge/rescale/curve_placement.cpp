#include "bridge/rescale/curve_placement.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "bridge/fit/least_squares.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

// The value for curve j of a list holding one value for all curves or one per curve.
std::optional<double> pick(const std::vector<double>& list, std::size_t j) {
  if (list.empty()) return std::nullopt;
  return list.size() == 1 ? list[0] : list[j];
}
// Least squares of the relative residuals (y_i − m_i(p))/y_i over log-parameters p;
// `model` fills m(p) and ∂m/∂p. Returns p and its standard errors (χ²/dof scaled).
struct RelativeFit {
  Eigen::VectorXd p, error;
};
RelativeFit fit_relative(
    const std::vector<double>& y, Eigen::VectorXd start,
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&, Eigen::MatrixXd&)>& model,
    const std::string& what) {
  const auto n = static_cast<Eigen::Index>(y.size());
  Eigen::VectorXd m(n);
  Eigen::MatrixXd dm(n, start.size());
  LeastSquaresProblem problem;
  problem.parameters = start.size();
  problem.residuals = n;
  problem.residual = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    model(p, m, dm);
    for (Eigen::Index i = 0; i < n; ++i) r(i) = (y[i] - m(i)) / y[i];
  };
  problem.jacobian = [&](const Eigen::VectorXd& p, Eigen::MatrixXd& jac) {
    model(p, m, dm);
    for (Eigen::Index i = 0; i < n; ++i) jac.row(i) = -dm.row(i) / y[i];
  };
  const LeastSquaresResult solved = solve_least_squares(problem, std::move(start));
  if (!solved.converged) throw NumericalError(what + ": the fit failed: " + solved.status);
  RelativeFit fit{solved.parameters,
                  (solved.covariance.diagonal() * solved.goodness.reduced_chi2()).cwiseSqrt()};
  return fit;
}

double rms(const std::vector<double>& v, const std::vector<bool>& used) {
  double sum = 0.0, count = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!used[i]) continue;
    sum += v[i] * v[i];
    ++count;
  }
  return std::sqrt(sum / count);
}

// The Herschel–Bulkley fit of the points in the window, relative weights, errors scaled.
HerschelBulkleyFit own_fit(const MeasuredCurve& c, const std::vector<bool>& used) {
  Curve curve;
  for (std::size_t i = 0; i < c.shear_rate.size(); ++i) {
    if (!used[i]) continue;
    curve.x.push_back(c.shear_rate[i]);
    curve.y.push_back(c.stress[i]);
    curve.se.push_back(c.stress[i]);
  }
  HerschelBulkleyFit fit = fit_herschel_bulkley(curve);
  fit.covariance *= fit.goodness.reduced_chi2();
  return fit;
}

}  // namespace

RescaledCurve place_curve(const MeasuredCurve& c, std::size_t j, const RescaleSettings& s) {
  RescaledCurve out;
  out.label = c.label;
  const std::size_t n = c.shear_rate.size();
  std::vector<double> rate, stress;
  for (std::size_t i = 0; i < n; ++i) {
    out.used.push_back(c.shear_rate[i] >= s.min_rate && c.shear_rate[i] <= s.max_rate);
    if (!out.used.back()) continue;
    rate.push_back(c.shear_rate[i]);
    stress.push_back(c.stress[i]);
  }
  const std::string what = fmt::format("curve '{}'", c.label);
  require(rate.size() >= 4, fmt::format("{}: {} point(s) in the rate window {} ... {} 1/s; a fit "
                                        "needs at least 4",
                                        what, rate.size(), s.min_rate, s.max_rate));
  out.herschel_bulkley = own_fit(c, out.used);
  const HerschelBulkleyFit& hb = out.herschel_bulkley;

  const std::optional<double> given_yield = pick(s.yield_stress, j);
  const std::optional<double> strain = pick(s.yield_strain, j), g0 = pick(s.shear_modulus, j);
  out.yield_stress_fitted = !given_yield;
  out.modulus_fitted = !s.modulus;
  if (given_yield && out.modulus_fitted) {
    // E* sets how fast the stress rises above τ_y: it needs points above it.
    const auto above = std::count_if(stress.begin(), stress.end(),
                                     [&](double t) { return t > *given_yield; });
    require(above >= 2,
            fmt::format("{}: the given yield stress {} Pa is not below the measured stresses ({} "
                        "of {} points in the rate window above it, largest {:.4g} Pa): E* cannot "
                        "be fitted from the rise above it; give the yield stress the curve "
                        "flows from",
                        what, *given_yield, above, stress.size(),
                        *std::max_element(stress.begin(), stress.end())));
  }
  if (!given_yield) {
    if (!hb.converged)
      throw NumericalError(what + ": the Herschel-Bulkley fit failed: " + hb.status);
    Curve window{rate, stress, stress};
    const PlateauCheck plateau = check_plateau(window, hb);
    require(plateau.ok,
            what + ": " + plateau.reason + "; or give the yield stress (--yield-stress)");
  }

  // τ_model = τ_y + k S(τ_y) √(γ̇ η_s/E*), S = G0 or τ_y/γ_y.
  const auto slope_scale = [&](double tau_y) { return g0 ? *g0 : tau_y / *strain; };
  const double d_scale = g0 ? 0.0 : 1.0 / *strain;  // dS/dτ_y
  double tau_y = given_yield.value_or(hb.parameters.yield);
  double e_star = s.modulus.value_or(0.0);
  if (!s.modulus) {
    // Start from the m = ½ law's slope c = k S √(η_s/E*).
    Curve relative{rate, stress, stress};
    const SquareRootLaw law = fit_square_root_law(relative);
    require(law.slope > 0, what + ": the stress does not grow with the rate; E* cannot be fitted");
    e_star = s.viscosity * std::pow(s.k * slope_scale(tau_y) / law.slope, 2);
  }
  Eigen::VectorXd start(static_cast<Eigen::Index>(out.yield_stress_fitted + out.modulus_fitted));
  Eigen::Index free = 0;
  if (out.yield_stress_fitted) start(free++) = std::log(tau_y);
  if (out.modulus_fitted) start(free++) = std::log(e_star);
  // Parameter index of ln τ_y and ln E* (−1: given).
  const Eigen::Index yield_slot = out.yield_stress_fitted ? 0 : -1;
  const Eigen::Index modulus_slot = out.modulus_fitted ? free - 1 : -1;
  const auto unpack = [&](const Eigen::VectorXd& p) {
    return std::pair(yield_slot >= 0 ? std::exp(p(yield_slot)) : tau_y,
                     modulus_slot >= 0 ? std::exp(p(modulus_slot)) : e_star);
  };
  double yield_error = 0.0, modulus_error = 0.0;
  if (free > 0) {
    const RelativeFit fit = fit_relative(
        stress, start,
        [&](const Eigen::VectorXd& p, Eigen::VectorXd& m, Eigen::MatrixXd& dm) {
          const auto [ty, es] = unpack(p);
          for (std::size_t i = 0; i < rate.size(); ++i) {
            const double root = std::sqrt(rate[i] * s.viscosity / es);
            m(i) = ty + s.k * slope_scale(ty) * root;
            if (yield_slot >= 0) dm(i, yield_slot) = ty * (1.0 + s.k * d_scale * root);
            if (modulus_slot >= 0) dm(i, modulus_slot) = -0.5 * s.k * slope_scale(ty) * root;
          }
        },
        what);
    std::tie(tau_y, e_star) = unpack(fit.p);
    if (yield_slot >= 0) yield_error = tau_y * fit.error(yield_slot);
    if (modulus_slot >= 0) modulus_error = e_star * fit.error(modulus_slot);
  }
  if (!(std::isfinite(tau_y) && std::isfinite(e_star) && std::isfinite(yield_error) &&
        std::isfinite(modulus_error) && tau_y > 0 && e_star > 0 && yield_error < tau_y &&
        modulus_error < e_star)) {
    throw NumericalError(fmt::format("{}: the fit gave tau_y = {:.3g} +- {:.3g} Pa, E* = {:.3g} "
                                     "+- {:.3g} Pa, which are not finite positive values known "
                                     "better than to a factor of two; the curve does not "
                                     "determine them",
                                     what, tau_y, yield_error, e_star, modulus_error));
  }
  out.yield_stress = {tau_y, yield_error};
  out.modulus = {e_star, modulus_error};
  out.yield_strain = g0 ? Estimate{tau_y / *g0, yield_error / *g0} : Estimate{*strain, 0.0};

  const double gamma_y = out.yield_strain.value;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = c.shear_rate[i] * s.viscosity / (e_star * gamma_y * gamma_y);
    const double model = 1.0 + s.k * std::sqrt(x);
    out.collapse_rate.push_back(x);
    out.stress_ratio.push_back(c.stress[i] / tau_y);
    out.residual.push_back(out.stress_ratio.back() / model - 1.0);
    if (out.used[i]) out.chi2 += std::pow(1.0 - tau_y * model / c.stress[i], 2);
  }
  out.rms_residual = rms(out.residual, out.used);

  // N1 = N1_y + k′ τ_y √x (fit/universal_law.h). N1_y is the one free
  // parameter: the mean over the window of N1 − k′ τ_y √x, of either sign. Its
  // residuals are in units of τ_y, which stay defined where N1 crosses zero
  // (relative ones would not, and would let the smallest |N1| rule the fit).
  if (c.N1) {
    const auto rate_term = [&](std::size_t i) {
      return s.k_N1 * tau_y * std::sqrt(out.collapse_rate[i]);
    };
    double sum = 0.0, count = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!out.used[i]) continue;
      sum += (*c.N1)[i] - rate_term(i);
      ++count;
    }
    const double n1_yield = sum / count;
    out.N1_ratio.emplace();
    out.N1_residual.emplace();
    for (std::size_t i = 0; i < n; ++i) {
      out.N1_ratio->push_back((*c.N1)[i] / tau_y);
      out.N1_residual->push_back(((*c.N1)[i] - n1_yield - rate_term(i)) / tau_y);
    }
    out.N1_rms_residual = rms(*out.N1_residual, out.used);
    // The standard error of a mean, with the scatter about the law (count − 1 dof).
    const double scatter = tau_y * *out.N1_rms_residual * std::sqrt(count / (count - 1.0));
    out.N1_yield = Estimate{n1_yield, scatter / std::sqrt(count)};
  }
  return out;
}

}  // namespace softglass::bridge
