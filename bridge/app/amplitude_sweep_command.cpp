// `bridge amplitude-sweep`: a material's amplitude sweep predicted from the
// law's (material/amplitude_sweep_prediction.h) and, with a measured one,
// compared point by point — the oscillatory counterpart of `macro compare`.
// A narrow-gap rheometer strains its sample nearly homogeneously, so the
// prediction needs no finite elements: the moduli are the material's own.
//
// The comparison splits the measured points at their own softening strain
// (G′ down to 0.9 of its plateau): the linear branch below, the nonlinear one
// above; each gets the median |error| and the mean signed error of G′ and G″.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bridge/app/command_support.h"
#include "bridge/app/commands.h"
#include "bridge/app/law_file.h"
#include "bridge/app/report.h"
#include "bridge/material/amplitude_sweep_prediction.h"
#include "common/errors.h"
#include "common/measured_curves.h"
#include "common/output_folder.h"
#include "common/overlay_plot.h"
#include "common/unit_table.h"

namespace softglass::bridge {

namespace {

// The prediction at strain γ, log-log between the simulated amplitudes.
double at_strain(const std::vector<double>& amplitudes, const std::vector<MaterialValue>& moduli,
                 double strain) {
  const auto upper = std::upper_bound(amplitudes.begin(), amplitudes.end(), strain);
  const std::size_t j =
      std::clamp<std::size_t>(upper - amplitudes.begin(), 1, amplitudes.size() - 1);
  const double w =
      std::log(strain / amplitudes[j - 1]) / std::log(amplitudes[j] / amplitudes[j - 1]);
  const double a = moduli[j - 1].value, b = moduli[j].value;
  if (a > 0 && b > 0) return std::exp((1 - w) * std::log(a) + w * std::log(b));
  return (1 - w) * a + w * b;
}

// The sweep `sample` of the file (its only one when empty), unless it has more
// points than a measured sweep has (common/measured_curves.h).
MeasuredAmplitudeSweep chosen_sweep(const std::filesystem::path& data, const std::string& format,
                                    const std::string& sample) {
  std::vector<MeasuredAmplitudeSweep> sweeps =
      read_amplitude_sweeps(read_measured_file(data, format));
  require(!sample.empty() || sweeps.size() == 1,
          fmt::format("'{}' holds {} amplitude sweeps: choose one with --sample", data.string(),
                      sweeps.size()));
  const auto chosen = sample.empty() ? sweeps.begin()
                                     : std::find_if(sweeps.begin(), sweeps.end(),
                                                    [&](const auto& s) { return s.label == sample; });
  require(chosen != sweeps.end(),
          fmt::format("'{}' has no curve labelled '{}'", data.string(), sample));
  require(chosen->strain.size() <= kMostMeasuredPoints,
          fmt::format("'{}': amplitude sweep '{}' has {} points; a measured one has tens, so this "
                      "is taken for another kind of file; allowed: at most {}",
                      data.string(), chosen->label, chosen->strain.size(), kMostMeasuredPoints));
  return *chosen;
}

struct BranchErrors {
  std::size_t points = 0;
  double storage_median = 0, storage_mean = 0, loss_median = 0, loss_mean = 0;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

BranchErrors branch_errors(const std::vector<double>& storage_error,
                           const std::vector<double>& loss_error) {
  BranchErrors b;
  b.points = storage_error.size();
  if (b.points == 0) return b;
  std::vector<double> s, l;
  for (std::size_t k = 0; k < b.points; ++k) {
    s.push_back(std::abs(storage_error[k]));
    l.push_back(std::abs(loss_error[k]));
    b.storage_mean += storage_error[k] / static_cast<double>(b.points);
    b.loss_mean += loss_error[k] / static_cast<double>(b.points);
  }
  b.storage_median = median(s);
  b.loss_median = median(l);
  return b;
}

// The comparison of a measured sweep with the prediction, printed and tabled.
struct Comparison {
  std::vector<double> strain, storage, loss, storage_predicted, loss_predicted, storage_error,
      loss_error;
  std::vector<bool> nonlinear;
  std::size_t outside = 0;  // measured points outside the simulated amplitudes
  Estimate measured_crossover, measured_softening;
  BranchErrors linear, yielded;
};

Comparison compare(const MeasuredAmplitudeSweep& m, const AmplitudeSweepPrediction& p) {
  Comparison c;
  std::vector<Estimate> storage, loss;  // no errors: the measurement's are not given
  for (std::size_t k = 0; k < m.strain.size(); ++k) {
    storage.push_back({m.storage[k], 0.0});
    loss.push_back({m.loss[k], 0.0});
  }
  const SweepStrains strains = sweep_strains(m.strain, storage, loss);
  c.measured_softening = strains.softening;
  c.measured_crossover = strains.crossover;
  std::vector<double> linear_s, linear_l, yielded_s, yielded_l;
  for (std::size_t k = 0; k < m.strain.size(); ++k) {
    const double g = m.strain[k];
    if (g < p.amplitudes.front() * (1 - 1e-9) || g > p.amplitudes.back() * (1 + 1e-9)) {
      ++c.outside;
      continue;
    }
    const double s = at_strain(p.amplitudes, p.storage, g), l = at_strain(p.amplitudes, p.loss, g);
    const bool beyond = c.measured_softening.value > 0 && g > c.measured_softening.value;
    c.strain.push_back(g);
    c.storage.push_back(m.storage[k]);
    c.loss.push_back(m.loss[k]);
    c.storage_predicted.push_back(s);
    c.loss_predicted.push_back(l);
    c.storage_error.push_back(s / m.storage[k] - 1.0);
    c.loss_error.push_back(l / m.loss[k] - 1.0);
    c.nonlinear.push_back(beyond);
    (beyond ? yielded_s : linear_s).push_back(c.storage_error.back());
    (beyond ? yielded_l : linear_l).push_back(c.loss_error.back());
  }
  c.linear = branch_errors(linear_s, linear_l);
  c.yielded = branch_errors(yielded_s, yielded_l);
  return c;
}

UnitTable prediction_table(const AmplitudeSweepPrediction& p) {
  UnitTable t{
      {{"gamma0", "1"}, {"storage", "Pa"}, {"storage_se", "Pa"}, {"loss", "Pa"}, {"loss_se", "Pa"}},
      {}};
  for (std::size_t k = 0; k < p.amplitudes.size(); ++k)
    t.rows.push_back({p.amplitudes[k], p.storage[k].value, p.storage[k].error(), p.loss[k].value,
                      p.loss[k].error()});
  return t;
}

UnitTable comparison_table(const Comparison& c) {
  UnitTable t{{{"gamma0", "1"},
               {"storage_measured", "Pa"},
               {"storage_predicted", "Pa"},
               {"storage_error", "1"},
               {"loss_measured", "Pa"},
               {"loss_predicted", "Pa"},
               {"loss_error", "1"},
               {"nonlinear", "1"}},
              {}};
  for (std::size_t k = 0; k < c.strain.size(); ++k)
    t.rows.push_back({c.strain[k], c.storage[k], c.storage_predicted[k], c.storage_error[k],
                      c.loss[k], c.loss_predicted[k], c.loss_error[k], c.nonlinear[k] ? 1.0 : 0.0});
  return t;
}

void print_comparison(const Comparison& c, const MeasuredAmplitudeSweep& m,
                      const AmplitudeSweepPrediction& p) {
  const auto strain = [](double v) {
    return v > 0 ? fmt::format("{:.4g}", v) : std::string("not reached");
  };
  fmt::print(
      "measured '{}': {} points, {} compared ({} outside the simulated amplitudes {:.3g} ... "
      "{:.3g})\n",
      m.label, m.strain.size(), c.strain.size(), c.outside, p.amplitudes.front(),
      p.amplitudes.back());
  if (m.angular_frequency)
    fmt::print(
        "frequency: measured at {:.4g} rad/s, predicted at {:.4g} rad/s (the law's omega~ "
        "at this E*, eta_s): ratio {:.3g}\n",
        *m.angular_frequency, p.angular_frequency, p.angular_frequency / *m.angular_frequency);
  fmt::print(
      "plateau G': measured {:.4g} Pa (gamma0 = {:.3g}), predicted {:.4g} Pa; G'': measured "
      "{:.4g} Pa, predicted {:.4g} Pa\n",
      m.storage.front(), m.strain.front(), p.plateau_storage.value, m.loss.front(),
      p.plateau_loss.value);
  fmt::print(
      "softening strain: measured {}, predicted {}; crossover strain: measured {}, "
      "predicted {}\n",
      strain(c.measured_softening.value), strain(p.softening_strain.value),
      strain(c.measured_crossover.value), strain(p.crossover_strain.value));
  for (const auto& [name, b] : {std::pair("linear (below the measured softening strain)", c.linear),
                                std::pair("nonlinear (above it)", c.yielded)}) {
    if (b.points == 0) continue;
    fmt::print(
        "  {}: {} points, G' median |error| {:.1f} % (mean {:+.1f} %), G'' median |error| "
        "{:.1f} % (mean {:+.1f} %)\n",
        name, b.points, 100 * b.storage_median, 100 * b.storage_mean, 100 * b.loss_median,
        100 * b.loss_mean);
  }
}

// G′ and G″ on one axis against the strain amplitude: every measured point,
// the predicted sweep over its simulated amplitudes, and below them the
// relative errors at the measured amplitudes the prediction covers.
OverlayPanel sweep_panel(const MeasuredAmplitudeSweep& measured, const AmplitudeSweepPrediction& p,
                         const Comparison& c) {
  const auto values = [](const std::vector<MaterialValue>& v) {
    std::vector<double> out;
    for (const MaterialValue& m : v) out.push_back(m.value);
    return out;
  };
  return {.quantity = "G', G'' [Pa]",
          .abscissa = "strain amplitude {/Symbol g}_0",
          .curves = {{"G' measured", measured.strain, measured.storage, false, 0},
                     {"G'' measured", measured.strain, measured.loss, false, 1},
                     {"G' predicted", p.amplitudes, values(p.storage), true, 0},
                     {"G'' predicted", p.amplitudes, values(p.loss), true, 1}},
          .errors = {relative_errors("G'", c.strain, c.storage, c.storage_predicted, 0),
                     relative_errors("G''", c.strain, c.loss, c.loss_predicted, 1)}};
}

}  // namespace

void amplitude_sweep_command(const AmplitudeSweepOptions& o, const std::string& command_line) {
  // Every input is read and checked, and the prediction and comparison made
  // (they take no time), before the folder is made: a refused command leaves
  // none behind.
  const Law law = read_law_file(o.law);
  std::optional<MeasuredAmplitudeSweep> measured;
  if (!o.data.empty()) measured = chosen_sweep(o.data, o.format, o.sample);
  std::vector<std::string> lines =
      provenance("softglass bridge amplitude-sweep: a material's amplitude sweep from a law file",
                 command_line);
  lines.push_back("law:      " + o.law.string());
  MaterialRequest request{o.phi, 0.0, o.viscosity, o.extrapolate};
  request.modulus = contact_modulus(o.source, law, o.phi, o.extrapolate, lines);
  const AmplitudeSweepPrediction p = predict_amplitude_sweep(law, request);
  std::optional<Comparison> c;
  if (measured) {
    c = compare(*measured, p);
    require(
        !c->strain.empty(),
        fmt::format("no measured strain of '{}' lies within the simulated amplitudes {:.3g} ... "
                    "{:.3g}",
                    o.data.string(), p.amplitudes.front(), p.amplitudes.back()));
  }

  const OutputFolder folder(o.output);
  AtomicOutput predicted_out(o.output / "amplitude_sweep.csv", o.force);
  std::optional<AtomicOutput> comparison_out, plot_out;
  if (measured) {
    comparison_out.emplace(o.output / "comparison.csv", o.force);
    plot_out.emplace(o.output / "comparison.png", o.force);
  }
  print_amplitude_sweep_prediction(p);
  lines.push_back(fmt::format("phi = {}, E* = {:.6g} Pa, eta_s = {:.6g} Pa s: omega = {:.4g} rad/s",
                              o.phi, request.modulus, o.viscosity, p.angular_frequency));
  if (std::isnan(p.plateau_storage.statistical))
    lines.push_back("storage_se, loss_se: nan (n/a) where the law's sweep is one packing's: no "
                    "scatter between packings to estimate them from");
  write_csv(predicted_out.temporary_path(), predicted_out.final_path(), lines, prediction_table(p),
            8);
  std::vector<AtomicOutput*> outputs{&predicted_out};
  if (measured) {
    print_comparison(*c, *measured, p);
    lines.push_back("measured: " + o.data.string() + ", curve '" + measured->label + "'");
    write_csv(comparison_out->temporary_path(), comparison_out->final_path(), lines,
              comparison_table(*c), 8);
    outputs.push_back(&*comparison_out);
    const OverlayPlot plot{
        .title = fmt::format("{}: amplitude sweep\npredicted: {}, phi = {}, E* = {:.4g} Pa",
                             o.data.filename().string(), o.law.filename().string(), o.phi,
                             request.modulus),
        .panels = {sweep_panel(*measured, p, *c)}};
    const PlotOutcome plotted = write_overlay_png(plot, plot_out->temporary_path());
    if (plotted.kind == PlotOutcome::Kind::write_failed) {
      throw NumericalError(
          fmt::format("cannot write '{}': {}", plot_out->final_path().string(), plotted.reason));
    }
    if (plotted.written()) {
      outputs.push_back(&*plot_out);
    } else {
      // An older plot (replaced with --force) would not show these numbers;
      // without --force a plot there is another process's result.
      if (o.force) std::filesystem::remove(plot_out->final_path());
      fmt::print("no plot: {}\n", plotted.reason);
    }
  }
  AtomicOutput::commit_together(outputs);
  for (const AtomicOutput* out : outputs) fmt::print("written  {}\n", out->final_path().string());
}

}  // namespace softglass::bridge
