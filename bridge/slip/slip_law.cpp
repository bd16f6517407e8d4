#include "bridge/slip/slip_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>

#include "bridge/material/interpolation.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

constexpr double kRelativeErrorFloor = 1e-8;  // the table's eight significant digits

struct LogPoints {
  Eigen::VectorXd x, y, sx2, sy2;  // ln σ̃, ln(Ṽ γ̃), their relative variances
};

LogPoints log_points(const std::vector<SlipPoint>& points) {
  const auto n = static_cast<Eigen::Index>(points.size());
  LogPoints l{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const SlipPoint& p = points[static_cast<std::size_t>(i)];
    l.x(i) = std::log(p.stress.value);
    l.y(i) = std::log(p.velocity.value);
    l.sx2(i) = std::pow(std::max(p.stress.error / p.stress.value, kRelativeErrorFloor), 2);
    l.sy2(i) = std::pow(std::max(p.velocity.error / p.velocity.value, kRelativeErrorFloor), 2);
  }
  return l;
}

// The straight line with errors in both coordinates and a scatter τ.
LeastSquaresResult fit_line(const LogPoints& l, double tau) {
  LeastSquaresProblem problem;
  problem.parameters = 2;
  problem.residuals = l.x.size();
  const auto variance = [&l, tau](const Eigen::VectorXd& q) {
    return (l.sy2 + q(1) * q(1) * l.sx2).array() + tau * tau;
  };
  problem.residual = [&l, variance](const Eigen::VectorXd& q, Eigen::VectorXd& r) {
    r = (l.y.array() - q(0) - q(1) * l.x.array()) / variance(q).sqrt();
  };
  problem.jacobian = [&l, variance](const Eigen::VectorXd& q, Eigen::MatrixXd& j) {
    const Eigen::ArrayXd w = variance(q).sqrt();
    const Eigen::ArrayXd d = l.y.array() - q(0) - q(1) * l.x.array();
    j.col(0) = (-1.0 / w).matrix();
    j.col(1) = (-l.x.array() / w - d * q(1) * l.sx2.array() / (w * w * w)).matrix();
  };
  // Start from the unweighted line.
  const double mx = l.x.mean(), my = l.y.mean();
  const double sxx = (l.x.array() - mx).square().sum();
  const double slope = ((l.x.array() - mx) * (l.y.array() - my)).sum() / sxx;
  Eigen::VectorXd start(2);
  start << my - slope * mx, slope;
  return solve_least_squares(problem, start);
}

}  // namespace

double SlipLawFit::pivot_stress() const {
  const double cov = correlation * log_coefficient.error * exponent.error;
  return exponent.error > 0 ? std::exp(-cov / (exponent.error * exponent.error))
                            : std::exp(0.5 * (std::log(stress_min) + std::log(stress_max)));
}

double SlipLawFit::pivot_error() const {
  return log_coefficient.error * std::sqrt(std::max(0.0, 1.0 - correlation * correlation));
}

SlipLawFit fit_slip_law(const std::vector<SlipPoint>& points) {
  require(points.size() >= 2,
          fmt::format("{} usable row{}: a slip law (A and p) needs at least 2", points.size(),
                      points.size() == 1 ? "" : "s"));
  const LogPoints l = log_points(points);
  require(l.x.maxCoeff() - l.x.minCoeff() > 1e-6,
          "every usable row has the same wall stress: the exponent p is undetermined");
  const int dof = static_cast<int>(points.size()) - 2;
  const LeastSquaresResult own = fit_line(l, 0.0);
  if (!own.converged) throw NumericalError("the slip-law fit did not converge: " + own.status);
  SlipLawFit f;
  f.goodness = own.goodness;
  LeastSquaresResult fit = own;
  if (dof > 0 && own.goodness.chi2 > dof) {
    // χ²_min(τ) falls as τ grows: bracket the τ where it equals dof.
    const auto excess = [&](double tau) { return fit_line(l, tau).goodness.chi2 - dof; };
    double hi = std::sqrt(own.goodness.chi2 / dof) * std::sqrt(l.sy2.maxCoeff() + l.sx2.maxCoeff());
    hi = std::max(hi, 1e-6);
    double at_hi = excess(hi);
    while (at_hi > 0 && hi < 1e3) at_hi = excess(hi *= 4);
    if (at_hi > 0) throw NumericalError("the slip-law fit found no scatter that explains its rows");
    std::uintmax_t iterations = 200;
    const auto [lo_tau, hi_tau] = boost::math::tools::toms748_solve(
        excess, 0.0, hi, own.goodness.chi2 - dof, at_hi,
        boost::math::tools::eps_tolerance<double>(40), iterations);
    f.scatter = 0.5 * (lo_tau + hi_tau);
    fit = fit_line(l, f.scatter);
    if (!fit.converged) throw NumericalError("the slip-law fit did not converge: " + fit.status);
  }
  if (!fit.covariance.allFinite())
    throw NumericalError("the slip-law fit's covariance is singular (rows too alike)");
  f.log_coefficient = {fit.parameters(0), std::sqrt(fit.covariance(0, 0))};
  f.exponent = {fit.parameters(1), std::sqrt(fit.covariance(1, 1))};
  const double coefficient = std::exp(f.log_coefficient.value);
  if (!(std::isfinite(coefficient) && coefficient > 0 && std::isfinite(f.exponent.value))) {
    throw InputError(fmt::format(
        "the slip law through these rows has ln A = {:.6g}, p = {:.6g}: A = exp(ln A) is not a "
        "representable number (slip velocities up to {:.3g}, wall stresses down to {:.3g}); are "
        "the rows in the reduced units of `micro slip` (gamma_dot R and E*)?",
        f.log_coefficient.value, f.exponent.value, std::exp(l.y.maxCoeff()),
        std::exp(l.x.minCoeff())));
  }
  const double denominator = f.log_coefficient.error * f.exponent.error;
  f.correlation = denominator > 0 ? fit.covariance(0, 1) / denominator : 0.0;
  f.points = points.size();
  f.stress_min = std::exp(l.x.minCoeff());
  f.stress_max = std::exp(l.x.maxCoeff());
  return f;
}

std::vector<SlipTableFit> fit_slip_table(const SlipTable& table,
                                         const std::function<double(double)>& stress_limit) {
  std::vector<double> phis;
  for (const SlipRow& r : table.rows)
    if (std::none_of(phis.begin(), phis.end(), [&](double p) { return std::abs(p - r.phi) < 1e-9; }))
      phis.push_back(r.phi);
  std::sort(phis.begin(), phis.end());
  std::vector<SlipTableFit> fits;
  for (const double phi : phis) {
    SlipTableFit t;
    t.stress_limit = stress_limit(phi);
    std::vector<SlipPoint> points;
    for (const SlipRow& r : table.rows) {
      if (std::abs(r.phi - phi) >= 1e-9) continue;
      t.rows.push_back(&r);
      t.fitted.push_back(r.wall_stress.value <= t.stress_limit);
      if (!t.fitted.back()) continue;
      points.push_back({r.wall_stress,
                        {r.slip_velocity.value * r.gamma_app, r.slip_velocity.error * r.gamma_app}});
    }
    try {
      t.law = fit_slip_law(points);
    } catch (const InputError& e) {
      const std::string limit =
          std::isfinite(t.stress_limit)
              ? fmt::format(" with wall stress <= {:.4g} E* ({} rows at this phi in all)",
                            t.stress_limit, t.rows.size())
              : "";
      throw InputError(fmt::format("{}: phi = {}{}: {}", table.source, phi, limit, e.what()));
    }
    t.law.phi = phi;
    fits.push_back(std::move(t));
  }
  return fits;
}

SlipLawAt slip_law_at(const std::vector<SlipTableFit>& fits, double phi, bool extrapolate) {
  require(!fits.empty(), "the slip table has no volume fraction");
  const double first = fits.front().law.phi, last = fits.back().law.phi;
  SlipLawAt at;
  at.phi = phi;
  at.extrapolated = phi < first - 1e-9 || phi > last + 1e-9;
  const std::string range =
      fits.size() == 1 ? fmt::format("{}", first) : fmt::format("{} ... {}", first, last);
  require(!at.extrapolated || extrapolate,
          fmt::format("phi = {} lies outside the slip table's volume fractions ({}); add "
                      "--extrapolate to use the nearest law (stated in the file), or simulate "
                      "this phi with `micro slip`",
                      phi, range));
  std::vector<double> phis;
  std::vector<Estimate> a, p, corr;
  for (const SlipTableFit& f : fits) {
    phis.push_back(f.law.phi);
    a.push_back(f.law.log_coefficient);
    p.push_back(f.law.exponent);
    corr.push_back({f.law.correlation, 0.0});
  }
  // The nearest neighbours bound the stress range the law rests on.
  const auto nearest = std::min_element(fits.begin(), fits.end(), [&](const auto& u, const auto& v) {
    return std::abs(u.law.phi - phi) < std::abs(v.law.phi - phi);
  });
  at.stress_min = nearest->law.stress_min;
  at.stress_max = nearest->law.stress_max;
  if (fits.size() == 1) {
    at.log_coefficient = a.front();
    at.exponent = p.front();
    at.correlation = corr.front().value;
    at.placement = at.extrapolated
                       ? fmt::format("EXTRAPOLATED: the law of the only simulated phi, {}, used at {}",
                                     first, phi)
                       : fmt::format("at the simulated volume fraction {}", first);
    return at;
  }
  const auto estimate = [&](const std::vector<Estimate>& g) {
    const Interpolated i = interpolate(phis, g, phi);
    const double extra = std::isfinite(i.interpolation) ? i.interpolation : 0.0;
    return Estimate{i.value, std::hypot(i.statistical, extra)};
  };
  at.log_coefficient = estimate(a);
  at.exponent = estimate(p);
  at.correlation = std::clamp(estimate(corr).value, -1.0, 1.0);
  at.placement = is_simulated(phis, phi) ? fmt::format("at the simulated volume fraction {}", phi)
                 : at.extrapolated
                     ? fmt::format("EXTRAPOLATED linearly from the volume fractions {}", range)
                     : fmt::format("interpolated linearly in phi between the simulated {}", range);
  return at;
}

double slip_coefficient_si(double coefficient, double exponent, double modulus, double viscosity,
                           double radius) {
  for (const auto& [name, value] : {std::pair("contact modulus E* [Pa]", modulus),
                                    std::pair("solvent viscosity eta_s [Pa s]", viscosity),
                                    std::pair("particle radius R [m]", radius)})
    require(std::isfinite(value) && value > 0,
            fmt::format("{} = {}: must be positive and finite", name, value));
  const double beta = coefficient * radius * std::pow(modulus, 1.0 - exponent) / viscosity;
  if (!std::isfinite(beta) || beta <= 0)
    throw InputError(fmt::format(
        "the slip coefficient beta = A R E*^(1-p)/eta_s = {} is not representable (A = {}, p = {}, "
        "E* = {} Pa)",
        beta, coefficient, exponent, modulus));
  return beta;
}

double slip_coefficient_relative_error(const SlipLawAt& law, double modulus) {
  const double sa = law.log_coefficient.error, sp = law.exponent.error, l = std::log(modulus);
  return std::sqrt(
      std::max(0.0, sa * sa + l * l * sp * sp - 2.0 * l * law.correlation * sa * sp));
}

std::string slip_law_text(const std::vector<std::string>& comments, double coefficient,
                          double exponent) {
  std::string text;
  for (const std::string& c : comments) text += "# " + c + "\n";
  text += fmt::format(
      "subsection slip\n"
      "  set law          = power-law\n"
      "  set coefficient  = {:.6g}   # beta [m/s/Pa^p]: V_s = beta sigma_w^p\n"
      "  set exponent     = {:.6g}   # p [1]\n"
      "  set yield stress = 0   # sigma_s [Pa]\n"
      "end\n",
      coefficient, exponent);
  return text;
}

}  // namespace softglass::bridge
