#include "bridge/material/prediction.h"

#include <fmt/format.h>

#include "common/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "common/errors.h"
#include "macro/material/herschel_bulkley.h"
#include "macro/material/tabulated_law.h"

namespace softglass::bridge {

namespace {

const Quantity kQuantities3[] = {Quantity::sigma, Quantity::N1, Quantity::N2};

// The material in reduced units (E* = η_s = 1: rates γ̃, stresses σ̃) as
// macro's laws — the simulated flow curve itself (the tabulated law) or its
// Herschel–Bulkley summary — with the simulated rows' bands (statistical and
// interpolation in φ, in quadrature) to interpolate in ln γ̃.
class ReducedCurve {
 public:
  ReducedCurve(const Law& law, const SimulatedCurves& curves, double phi, bool extrapolate,
               LawForm form)
      : table_(make_tabulated_material(law, curves, {phi, 1.0, 1.0, extrapolate})) {
    macro::FlowTable flow{.yield_stress = table_.yield.value, .rates = {}, .stresses = {}};
    for (const TabulatedRow& row : table_.rows) {
      flow.rates.push_back(row.rate);
      flow.stresses.push_back(row.value[index(Quantity::sigma)]->value);
      log_rates_.push_back(std::log(row.rate));
    }
    if (form == LawForm::herschel_bulkley) {
      const Material hb = make_material(law, {phi, 1.0, 1.0, extrapolate});
      const auto triple = [&hb](Quantity q) { return *hb.laws[index(q)]; };
      const MaterialLaw s = triple(Quantity::sigma);
      shear_ = macro::shear_law(macro::HerschelBulkley{
          .yield_stress = s.yield.value, .consistency = s.consistency.value,
          .flow_index = s.index.value});
      yield_ = s.yield;
      for (const Quantity q : {Quantity::N1, Quantity::N2})
        if (hb.laws[index(q)] && table_.rows.front().value[index(q)]) {
          const MaterialLaw n = triple(q);
          normal_[index(q)] = macro::normal_stress_curve(macro::NormalStressLaw{
              .yield = n.yield.value, .consistency = n.consistency.value,
              .flow_index = n.index.value});
        }
      return;
    }
    shear_ = macro::tabulated_law(flow);
    yield_ = table_.yield;
    for (const Quantity q : {Quantity::N1, Quantity::N2}) {
      if (!table_.rows.front().value[index(q)]) continue;
      std::vector<double> values;
      for (const TabulatedRow& row : table_.rows) values.push_back(row.value[index(q)]->value);
      const double rest = table_.rest[index(q)] ? table_.rest[index(q)]->value : 0.0;
      normal_[index(q)] =
          macro::tabulated_normal_stress(flow, rest, std::move(values), column_name(q));
    }
  }

  bool has(Quantity q) const { return q == Quantity::sigma || normal_[index(q)] != nullptr; }
  double yield() const { return yield_.value; }
  double yield_error() const { return yield_.statistical; }

  double value(Quantity q, double gamma) const {
    return q == Quantity::sigma ? shear_->stress(gamma) : normal_[index(q)]->value(gamma);
  }
  /// d ln σ̃/d ln γ̃ = Δ n/σ̃ (the yield stress does not change with the rate).
  double slope(double gamma) const {
    const auto [excess, n] = shear_->excess_and_flow_index(gamma);
    return excess * n / (shear_->yield_stress() + excess);
  }
  bool outside(double gamma) const {
    const double x = std::log(gamma);
    return x < log_rates_.front() || x > log_rates_.back();
  }
  /// The rows' band at γ̃, linear in ln γ̃ between rows, the end row's outside.
  double band(Quantity q, double gamma) const {
    const double x = std::clamp(std::log(gamma), log_rates_.front(), log_rates_.back());
    const auto above = std::upper_bound(log_rates_.begin(), log_rates_.end(), x);
    const std::size_t k = std::min<std::size_t>(
        above == log_rates_.begin() ? 0 : std::size_t(above - log_rates_.begin()) - 1,
        log_rates_.size() - 2);
    const double t = (x - log_rates_[k]) / (log_rates_[k + 1] - log_rates_[k]);
    return (1.0 - t) * table_.rows[k].value[index(q)]->error() +
           t * table_.rows[k + 1].value[index(q)]->error();
  }

 private:
  TabulatedMaterial table_;
  MaterialValue yield_;
  std::vector<double> log_rates_;
  std::shared_ptr<const macro::ShearLaw> shear_;
  std::shared_ptr<const macro::NormalStressCurve> normal_[kQuantities];
};

// E* of mode (d): the minimum over u = ln E* of S(u) = Σ (ln τ(γ̇_i) − ln τ_i)²,
// found on a grid of 1/20 decade over 1e-3 … 1e9 Pa and refined by golden
// sections; its error from the curvature of S at the minimum (Gauss–Newton:
// var u = S/(N − 1) / Σ J_i², J_i = d ln τ/d ln E* = 1 − s_i).
MaterialValue fit_modulus(const ReducedCurve& curve, const MeasuredCurve& measured,
                          double viscosity, std::vector<std::string>& notes) {
  const std::size_t n = measured.shear_rate.size();
  const auto misfit = [&](double u) {
    const double e_star = std::exp(u);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = std::log(e_star * curve.value(Quantity::sigma,
                                                     measured.shear_rate[i] * viscosity / e_star)) -
                       std::log(measured.stress[i]);
      sum += r * r;
    }
    return sum;
  };
  const double lo = std::log(1e-3), hi = std::log(1e9), step = std::log(10.0) / 20.0;
  double best = lo;
  for (double u = lo; u <= hi; u += step)
    if (misfit(u) < misfit(best)) best = u;
  double a = best - step, b = best + step;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  while (b - a > 1e-10) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (misfit(c) < misfit(d))
      b = d;
    else
      a = c;
  }
  const double u = 0.5 * (a + b), e_star = std::exp(u);
  require(u > lo + step && u < hi - step,
          fmt::format("mode (d): the best E* lies at the end of the range searched (1e-3 ... 1e9 "
                      "Pa): the measured curve '{}' is not a flow curve of this law",
                      measured.label));
  double jacobian = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = curve.slope(measured.shear_rate[i] * viscosity / e_star);
    jacobian += (1.0 - s) * (1.0 - s);
  }
  const double rms = std::sqrt(misfit(u) / n);
  const double error = n > 1 && jacobian > 0.0
                           ? e_star * std::sqrt(misfit(u) / double(n - 1) / jacobian)
                           : std::numeric_limits<double>::quiet_NaN();
  notes.push_back(fmt::format(
      "E* = {:.6g} Pa +- {:.2g} % fitted to the measured curve '{}' ({} points, {:.4g} ... {:.4g} "
      "1/s; rms misfit of ln tau {:.3g}, i.e. {:.2g} %)",
      e_star, 100.0 * error / e_star, measured.label, n, measured.shear_rate.front(),
      measured.shear_rate.back(), rms, 100.0 * std::expm1(rms)));
  return {e_star, error, 0.0};
}

}  // namespace

std::string mode_name(PredictionMode mode) {
  switch (mode) {
    case PredictionMode::nothing_fitted: return "(a) nothing fitted";
    case PredictionMode::plateau_modulus: return "(b) E* from the measured G'";
    case PredictionMode::yield_stress: return "(c) measured yield stress";
    case PredictionMode::fitted_modulus: return "(d) E* fitted to one measured flow curve";
  }
  return {};
}

PredictionMode prediction_mode(const PredictionInputs& in) {
  const bool modulus = in.modulus.has_value(), plateau = in.plateau_modulus.has_value();
  require(!(modulus && plateau),
          "give E* (--modulus, or --interfacial-tension with --radius) or the measured G' "
          "(--plateau-modulus), not both: each sets E*");
  if (in.measured_curve) {
    require(!modulus && !plateau && !in.yield_stress,
            "mode (d) fits E* to the measured curve: give no --modulus, --plateau-modulus or "
            "--yield-stress with it");
    return PredictionMode::fitted_modulus;
  }
  if (in.yield_stress) {
    require(*in.yield_stress > 0 && std::isfinite(*in.yield_stress),
            fmt::format("--yield-stress = {} Pa must be positive", *in.yield_stress));
    require(modulus || plateau,
            "mode (c) needs the measured G' (--plateau-modulus) or E* (--modulus) beside "
            "--yield-stress: they set the rates");
    return PredictionMode::yield_stress;
  }
  if (plateau) return PredictionMode::plateau_modulus;
  require(modulus, "no E*: give --modulus, --interfacial-tension with --radius, "
                   "--plateau-modulus (a measured G'), or a measured curve to fit it to");
  return PredictionMode::nothing_fitted;
}

namespace {

// The model's systematic error of the mode (model_error.h), per point by its
// branch (plateau: the predicted stress below 1.5× the predicted yield
// stress, as the scoreboard splits the measured points), and a note naming
// the data sets; or a note that it has not been measured.
void state_model_error(Prediction& p, const PredictionInputs& in, double yield_stress) {
  const char letter = "abcd"[static_cast<int>(p.mode)];
  const std::string form = in.form == LawForm::tabulated ? "tabulated" : "herschel-bulkley";
  const auto entry = [&](const char* branch) -> const ModelErrorEntry* {
    if (!in.model_error) return nullptr;
    const auto it = in.model_error->find({letter, form, branch});
    return it == in.model_error->end() ? nullptr : &it->second;
  };
  const ModelErrorEntry *plateau = entry("plateau"), *flowing = entry("flowing");
  if (!plateau || !flowing) {
    p.notes.push_back(fmt::format(
        "the model's systematic error in mode {} ({}): not measured{} (bench/validate_measured.sh "
        "scores it against public data sets; mode (a) needs an interfacial tension none gives)",
        letter, form, in.model_error ? "" : ", no LAW_model_error.csv beside the law"));
    return;
  }
  for (PredictedPoint& point : p.points) {
    const double tau = point.value[index(Quantity::sigma)]->value;
    point.model_error = (tau < 1.5 * yield_stress ? plateau : flowing)->median_abs_error * tau;
  }
  p.notes.push_back(fmt::format(
      "the model's systematic error in mode {} ({}), the column shear_stress_model_error: the "
      "median |predicted/measured - 1| of the scoreboard, {:.1f} % on the yield plateau (bias "
      "{:+.1f} %) and {:.1f} % on the flowing branch (bias {:+.1f} %), over {} ({} points; "
      "N1, N2: no measured data)",
      letter, form, 100 * plateau->median_abs_error, 100 * plateau->bias,
      100 * flowing->median_abs_error, 100 * flowing->bias, flowing->data_sets,
      plateau->points + flowing->points));
}

// The mode's scales: E* (the one that sets the rates), the stress scale (E*,
// or τ_y,m/σ̃_y in mode c) with its relative error, and the factor s on γ̃.
PredictionScales resolve_scales(const Law& law, const ReducedCurve& curve,
                                const PredictionInputs& in) {
  PredictionScales p;
  p.mode = prediction_mode(in);
  require(in.viscosity > 0 && std::isfinite(in.viscosity),
          fmt::format("solvent viscosity eta_s = {} Pa s must be positive", in.viscosity));
  p.notes.push_back(in.form == LawForm::tabulated
                        ? "law: the simulated flow curve itself (tabulated, monotone cubic in "
                          "log-log between the simulated rates)"
                        : "law: the Herschel-Bulkley summary of the simulated flow curve (bridge "
                          "fit's per-phi tau_y, K, n)");
  switch (p.mode) {
    case PredictionMode::nothing_fitted:
      p.modulus = {*in.modulus, 0.0, 0.0};
      break;
    case PredictionMode::plateau_modulus:
      p.modulus = contact_modulus_from_plateau(law, in.phi, *in.plateau_modulus, in.extrapolate);
      p.notes.push_back(fmt::format("E* = G' / (G0/E*)(phi) = {:.6g} Pa {}", p.modulus.value,
                                    relative_error_text(p.modulus)));
      break;
    case PredictionMode::fitted_modulus:
      p.modulus = fit_modulus(curve, *in.measured_curve, in.viscosity, p.notes);
      break;
    case PredictionMode::yield_stress: {
      p.modulus = in.plateau_modulus ? contact_modulus_from_plateau(law, in.phi,
                                                                    *in.plateau_modulus,
                                                                    in.extrapolate)
                                     : MaterialValue{*in.modulus, 0.0, 0.0};
      p.stress_scale = *in.yield_stress / curve.yield();
      p.stress_scale_error = curve.yield_error() / curve.yield();
      std::string rates_note = "rates at the simulated yield strain (no G' given)";
      if (in.plateau_modulus) {
        const double g0 = interpolate_value(law.phi, law.modulus, in.phi).value;
        const double simulated = curve.yield() / g0, measured = *in.yield_stress / *in.plateau_modulus;
        p.rate_factor = (simulated / measured) * (simulated / measured);
        rates_note = fmt::format(
            "rates rescaled by the yield strains, gamma~ x (gamma_y/gamma_y,m)^2 = x {:.4g} "
            "(simulated gamma_y = {:.4g}, measured tau_y/G' = {:.4g})",
            p.rate_factor, simulated, measured);
      }
      p.notes.push_back(fmt::format(
          "stresses scaled by the measured yield stress: tau_y,m / sigma~_y = {:.6g} Pa / {:.6g} "
          "= {:.6g} Pa (+- {:.2g} % from sigma~_y); {}; E* = {:.6g} Pa",
          *in.yield_stress, curve.yield(), p.stress_scale, 100.0 * p.stress_scale_error,
          rates_note, p.modulus.value));
      break;
    }
  }
  const double e_star = p.modulus.value;
  require(e_star > 0 && std::isfinite(e_star),
          fmt::format("contact modulus E* = {} Pa must be positive", e_star));
  if (p.mode != PredictionMode::yield_stress) {
    p.stress_scale = e_star;
    p.stress_scale_error = p.modulus.error() / e_star;
  }
  return p;
}

}  // namespace

PredictionScales prediction_scales(const Law& law, const SimulatedCurves& curves,
                                   const PredictionInputs& in) {
  return resolve_scales(law, ReducedCurve(law, curves, in.phi, in.extrapolate, in.form), in);
}

Prediction predict(const Law& law, const SimulatedCurves& curves, const PredictionInputs& in,
                   const std::vector<double>& rates) {
  for (const double r : rates)
    require(r > 0 && std::isfinite(r), fmt::format("shear rate {} 1/s must be positive", r));
  const ReducedCurve curve(law, curves, in.phi, in.extrapolate, in.form);
  const PredictionScales scales = resolve_scales(law, curve, in);
  Prediction p{.mode = scales.mode, .modulus = scales.modulus, .notes = scales.notes, .points = {}};
  const double e_star = p.modulus.value, scale = scales.stress_scale,
               scale_error = scales.stress_scale_error, rate_factor = scales.rate_factor;
  const double modulus_error = std::isnan(p.modulus.error()) ? 0.0 : p.modulus.error() / e_star;
  for (const double rate : rates) {
    const double gamma = rate * in.viscosity / e_star * rate_factor;
    PredictedPoint point{
        .rate = rate, .value = {}, .extrapolated = curve.outside(gamma), .model_error = {}};
    for (const Quantity q : kQuantities3) {
      if (!curve.has(q)) continue;
      const double value = scale * curve.value(q, gamma);
      // E* scales stresses and divides rates: d ln τ/d ln E* = 1 − s.
      const double moved =
          p.mode == PredictionMode::yield_stress
              ? std::hypot(scale_error, curve.slope(gamma) * modulus_error)
              : (1.0 - curve.slope(gamma)) * (std::isnan(scale_error) ? 0.0 : scale_error);
      point.value[index(q)] =
          Band{value, std::hypot(scale * curve.band(q, gamma), value * moved)};
    }
    p.points.push_back(point);
  }
  p.notes.push_back(
      "band (one standard deviation): the packings' statistical error of the simulated points "
      "and the interpolation between simulated phi, propagated, in quadrature with the scale's "
      "error above");
  if (std::isnan(p.modulus.error()))
    p.notes.push_back(
        "the law has one packing at this phi: the scatter of G0 between packings is n/a and left "
        "out of the band, which is therefore a lower bound");
  state_model_error(p, in, scale * curve.yield());
  return p;
}

TabulatedMaterial tabulated_material_in_mode(const Law& law, const SimulatedCurves& curves,
                                             const PredictionInputs& in,
                                             const PredictionScales& scales) {
  const double e_star = scales.modulus.value;
  TabulatedMaterial m =
      make_tabulated_material(law, curves, {in.phi, e_star, in.viscosity, in.extrapolate});
  // The E* table has τ_i = E* σ̃_i at γ̇_i = γ̃_i E*/η_s; mode (c) wants
  // scale × σ̃_i at γ̇_i/s.
  m.source = mode_name(scales.mode);
  const double factor = scales.stress_scale / e_star;
  const auto scaled = [factor](MaterialValue& v) {
    v = {factor * v.value, factor * v.statistical, factor * v.interpolation};
  };
  scaled(m.yield);
  for (auto& rest : m.rest)
    if (rest) scaled(*rest);
  for (auto* rows : {&m.rows, &m.plateau_rows})
    for (TabulatedRow& row : *rows) {
      row.rate /= scales.rate_factor;
      for (auto& v : row.value)
        if (v) scaled(*v);
    }
  return m;
}

std::string prediction_table(const Prediction& p, const std::vector<std::string>& provenance) {
  std::vector<std::string> comments = provenance;
  comments.push_back(fmt::format("mode: {}", mode_name(p.mode)));
  comments.insert(comments.end(), p.notes.begin(), p.notes.end());
  const PredictedPoint& first = p.points.front();
  std::vector<Quantity> present;
  for (const Quantity q : kQuantities3)
    if (first.value[index(q)]) present.push_back(q);
  const auto name = [](Quantity q) {
    return q == Quantity::sigma ? std::string("shear_stress") : std::string(column_name(q));
  };
  std::vector<Column> columns = {{"shear_rate", "1/s"}};
  for (const Quantity q : present) columns.push_back({name(q), "Pa"});
  for (const Quantity q : present) columns.push_back({name(q) + "_band", "Pa"});
  const bool model_error = first.model_error.has_value();
  if (model_error) columns.push_back({"shear_stress_model_error", "Pa"});
  columns.push_back({"extrapolated", "1"});
  CsvWriter table("the prediction", columns, comments);
  for (const PredictedPoint& point : p.points) {
    table << point.rate;
    for (const Quantity q : present) table << point.value[index(q)]->value;
    for (const Quantity q : present) table << point.value[index(q)]->band;
    if (model_error) table << *point.model_error;
    table << (point.extrapolated ? 1.0 : 0.0);
    table.end_row();
  }
  return table.text();
}

}  // namespace softglass::bridge
