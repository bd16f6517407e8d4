#include "macro/material/tabulated_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "macro/numerics/monotone_cubic.h"
#include "macro/numerics/root_finding.h"

namespace softglass::macro {

namespace {

// The largest exponent an end of the table may continue with: a material
// file's largest flow index.
constexpr double kLargestEndExponent = 2.0;

void check_table(const FlowTable& t) {
  const auto refuse = [](const std::string& what) {
    throw InputError(fmt::format("material (tabulated): {}", what));
  };
  if (!std::isfinite(t.yield_stress) || t.yield_stress < 0.0)
    refuse(fmt::format("'yield stress' = {} is not allowed; allowed: >= 0 Pa", t.yield_stress));
  if (t.rates.size() < 2)
    refuse(fmt::format("'rates' has {} value(s); allowed: at least 2", t.rates.size()));
  if (t.stresses.size() != t.rates.size())
    refuse(fmt::format("'stresses' has {} values and 'rates' {}; allowed: one stress per rate",
                       t.stresses.size(), t.rates.size()));
  for (std::size_t i = 0; i < t.rates.size(); ++i) {
    const double r = t.rates[i], s = t.stresses[i];
    if (!std::isfinite(r) || r <= 0.0)
      refuse(fmt::format("rate {} = {} [1/s] is not allowed; allowed: finite, > 0", i + 1, r));
    if (!std::isfinite(s))
      refuse(fmt::format("stress {} = {} [Pa] is not allowed; allowed: finite", i + 1, s));
    if (i > 0 && r <= t.rates[i - 1])
      refuse(fmt::format("rate {} = {} [1/s] does not exceed rate {} = {}; allowed: strictly "
                         "increasing rates",
                         i + 1, r, i, t.rates[i - 1]));
    if (i > 0 && s <= t.stresses[i - 1])
      refuse(fmt::format(
          "stress {} = {} [Pa] at {} 1/s does not exceed stress {} = {}; allowed: a flow curve "
          "increasing with the rate (a decreasing one is unstable flow, not a material law)",
          i + 1, s, r, i, t.stresses[i - 1]));
  }
  if (t.stresses.front() <= t.yield_stress)
    refuse(fmt::format("stress 1 = {} [Pa] does not exceed 'yield stress' = {} [Pa]; allowed: "
                       "every tabulated stress above the yield stress",
                       t.stresses.front(), t.yield_stress));
}

// ln Δ against ln γ̇ at the table's rows.
numerics::MonotoneCubic log_excess(const FlowTable& t) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < t.rates.size(); ++i) {
    x.push_back(std::log(t.rates[i]));
    y.push_back(std::log(t.stresses[i] - t.yield_stress));
  }
  return {std::move(x), std::move(y)};
}

// The end slopes of the monotone cubic are its end secants (monotone_cubic.h):
// the exponents of the continuations below and above the window.
std::pair<double, double> end_exponents(const numerics::MonotoneCubic& p) {
  return {p.slopes().front(), p.slopes().back()};
}

class TabulatedLaw final : public ShearLaw {
 public:
  explicit TabulatedLaw(const FlowTable& table)
      : yield_stress_(table.yield_stress), p_(log_excess(table)) {
    std::tie(n_lo_, n_hi_) = end_exponents(p_);
    for (const auto& [end, n] : {std::pair{"lowest", n_lo_}, std::pair{"highest", n_hi_}})
      require(n > 0.0 && n <= kLargestEndExponent,
              fmt::format("material (tabulated): the flow curve's exponent over its {} interval "
                          "is {:.4g}; allowed: 0 < n <= {:g} (it continues the law outside "
                          "the table)",
                          end, n, kLargestEndExponent));
    x_lo_ = p_.nodes().front();
    x_hi_ = p_.nodes().back();
  }

  std::string name() const override { return "tabulated"; }
  std::string description() const override {
    return fmt::format(
        "tabulated: tau_y = {} Pa, {} rates {:.4g} ... {:.4g} 1/s (monotone cubic in log-log); "
        "extrapolated as power laws outside: n = {:.4g} below, {:.4g} above",
        yield_stress_, p_.nodes().size(), std::exp(x_lo_), std::exp(x_hi_), n_lo_, n_hi_);
  }
  double yield_stress() const override { return yield_stress_; }

  double excess_stress(double rate) const override {
    if (rate <= 0.0) return 0.0;
    return excess_and_flow_index(rate).first;
  }
  double stress(double rate) const override { return yield_stress_ + excess_stress(rate); }

  double rate_at_excess(double excess) const override {
    if (excess <= 0.0) return 0.0;
    const double w = std::log(excess);
    const double y_lo = p_.values().front(), y_hi = p_.values().back();
    if (w <= y_lo) return std::exp(x_lo_ + (w - y_lo) / n_lo_);
    if (w >= y_hi) return std::exp(x_hi_ + (w - y_hi) / n_hi_);
    return std::exp(p_.inverse(w));
  }

  std::optional<std::pair<double, double>> rate_window() const override {
    return std::pair{std::exp(x_lo_), std::exp(x_hi_)};
  }

  std::vector<double> excess_breakpoints() const override {
    std::vector<double> out;
    for (const double y : p_.values()) out.push_back(std::exp(y));
    return out;
  }

  double local_flow_index(double rate) const override {
    return excess_and_flow_index(rate).second;
  }

  // ln Δ = P(ln γ̇) inside the window, the end power laws outside.
  std::pair<double, double> excess_and_flow_index(double rate) const override {
    const double x = std::log(rate);
    if (x <= x_lo_) return {std::exp(p_.values().front() + n_lo_ * (x - x_lo_)), n_lo_};
    if (x >= x_hi_) return {std::exp(p_.values().back() + n_hi_ * (x - x_hi_)), n_hi_};
    const auto [log_excess, n] = p_.value_and_derivative(x);
    return {std::exp(log_excess), n};
  }

  // On an interval of width h the cubic's slope is a quadratic in t ∈ [0, 1]:
  // its extremes are the node slopes and, where the slope's own derivative
  // vanishes inside, at t* = (6y0 + 4hd0 − 6y1 + 2hd1)/(12y0 + 6hd0 − 12y1 + 6hd1).
  std::pair<double, double> flow_index_range() const override {
    double lo = std::min(n_lo_, n_hi_), hi = std::max(n_lo_, n_hi_);
    const auto &x = p_.nodes(), &y = p_.values(), &d = p_.slopes();
    for (std::size_t k = 0; k + 1 < x.size(); ++k) {
      const double h = x[k + 1] - x[k];
      std::vector<double> n{d[k], d[k + 1]};
      const double den = 12 * y[k] + 6 * h * d[k] - 12 * y[k + 1] + 6 * h * d[k + 1];
      const double t = den != 0.0 ? (6 * y[k] + 4 * h * d[k] - 6 * y[k + 1] + 2 * h * d[k + 1]) / den
                                  : -1.0;
      if (t > 0.0 && t < 1.0) n.push_back(p_.derivative(x[k] + t * h));
      lo = std::min(lo, *std::min_element(n.begin(), n.end()));
      hi = std::max(hi, *std::max_element(n.begin(), n.end()));
    }
    return {lo, hi};
  }

  double viscosity(double rate) const override { return stress(rate) / rate; }

  double rate(double stress) const override {
    return stress <= yield_stress_ ? 0.0 : rate_at_excess(stress - yield_stress_);
  }

  // s = 0 if χ ≤ τ_y, else Δ(s) + r s = χ − τ_y: both terms increase from 0,
  // so the root lies below the rate at which either alone reaches χ − τ_y.
  double proximal_rate(double trial_stress, double penalty) const override {
    const double excess = trial_stress - yield_stress_;
    if (excess <= 0.0) return 0.0;
    double upper = rate_at_excess(excess);
    if (penalty == 0.0) return upper;
    upper = std::min(upper, excess / penalty);
    return numerics::solve_increasing(
        [&](double s) { return excess_stress(s) + penalty * s - excess; }, 0.0, upper,
        "tabulated law proximal rate");
  }

 private:
  double yield_stress_;
  numerics::MonotoneCubic p_;
  double n_lo_ = 0.0, n_hi_ = 0.0, x_lo_ = 0.0, x_hi_ = 0.0;

};

class TabulatedNormalStress final : public NormalStressCurve {
 public:
  TabulatedNormalStress(const FlowTable& table, double rest, std::vector<double> values)
      : rest_(rest), n_(end_exponents(log_excess(table))), p_(log_rates(table), std::move(values)) {}

  double value(double rate) const override {
    if (rate <= 0.0) return rest_;
    const double x = std::log(rate), x_lo = p_.nodes().front(), x_hi = p_.nodes().back();
    if (x < x_lo) return rest_ + (p_.values().front() - rest_) * std::exp(n_.first * (x - x_lo));
    if (x > x_hi) return rest_ + (p_.values().back() - rest_) * std::exp(n_.second * (x - x_hi));
    return p_.value(x);
  }
  bool vanishes() const override { return false; }
  std::vector<double> rate_breakpoints() const override {
    std::vector<double> out;
    for (const double x : p_.nodes()) out.push_back(std::exp(x));
    return out;
  }

 private:
  double rest_;
  std::pair<double, double> n_;
  numerics::MonotoneCubic p_;

  static std::vector<double> log_rates(const FlowTable& table) {
    std::vector<double> x;
    for (const double r : table.rates) x.push_back(std::log(r));
    return x;
  }
};

}  // namespace

std::shared_ptr<const ShearLaw> tabulated_law(const FlowTable& table) {
  check_table(table);
  return std::make_shared<TabulatedLaw>(table);
}

std::shared_ptr<const NormalStressCurve> tabulated_normal_stress(const FlowTable& table,
                                                                 double rest,
                                                                 std::vector<double> values,
                                                                 const std::string& name) {
  check_table(table);
  require(values.size() == table.rates.size(),
          fmt::format("material (tabulated): '{} values' has {} values and 'rates' {}; allowed: "
                      "one value per rate",
                      name, values.size(), table.rates.size()));
  require(std::isfinite(rest), fmt::format("material (tabulated): '{} yield' = {} is not "
                                           "allowed; allowed: a finite number",
                                           name, rest));
  for (std::size_t i = 0; i < values.size(); ++i)
    require(std::isfinite(values[i]),
            fmt::format("material (tabulated): {} value {} = {} is not allowed; allowed: finite",
                        name, i + 1, values[i]));
  return std::make_shared<TabulatedNormalStress>(table, rest, std::move(values));
}

}  // namespace softglass::macro
