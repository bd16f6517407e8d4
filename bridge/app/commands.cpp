#include "bridge/app/commands.h"

#include "bridge/app/command_support.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <ctime>
#include <sstream>

#include "bridge/app/law_file.h"
#include "bridge/app/report.h"
#include "bridge/law/crossover_estimate.h"
#include "bridge/law/law.h"
#include "bridge/material/material.h"
#include "bridge/material/prediction.h"
#include "bridge/material/tabulated_material.h"
#include "bridge/output/tables.h"
#include "bridge/rescale/law_yield_strain.h"
#include "bridge/sweep/analysis.h"
#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/progress.h"
#include "common/version.h"

namespace softglass::bridge {

namespace {

// The comment lines that open a law file (its provenance), without '#' and
// without the explanations law_text writes after the provenance itself.
std::vector<std::string> header_comments(const std::filesystem::path& file) {
  const std::string own = law_text(Law{});  // the explanations alone
  std::istringstream in(read_input_text(file, "law file", kParameterFileLimits));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line) && line.starts_with("#");)
    if (own.find(line + "\n") == std::string::npos)
      lines.push_back(line.substr(line.starts_with("# ") ? 2 : 1));
  return lines;
}

// `bridge fit --law LAW --oscillation TABLE`: the law's flow laws kept, its
// amplitude sweep added or replaced.
void add_amplitude_sweep(const FitOptions& o, const std::string& command_line) {
  AtomicOutput law_out(o.output, o.force);
  Law law = read_law_file(o.law);
  law.provenance = header_comments(o.law);
  const OscillationTable table = read_oscillation_table(CsvTable::read(o.oscillation));
  for (const std::string& w : table.warnings) fmt::print("WARNING:  {}: {}\n", table.source, w);
  law.amplitude_sweep = make_amplitude_sweep_law(table, o.oscillation_frequency);
  for (const std::string& line :
       provenance("softglass bridge fit: an amplitude sweep added to a law", command_line))
    law.provenance.push_back(line);
  law.provenance.push_back(fmt::format("amplitude sweep: {} at omega~ = {:.6g}",
                                       o.oscillation.string(), law.amplitude_sweep->frequency));
  print_amplitude_sweep_report(law);
  write(law_out, law_text(law));
  law_out.commit();
  fmt::print("written  {}\n", law_out.final_path().string());
}

}  // namespace

void fit_command(const FitOptions& o, const std::string& command_line) {
  if (!o.law.empty()) return add_amplitude_sweep(o, command_line);
  // Refuse early, before any work, if a result exists.
  AtomicOutput law_out(o.output, o.force), phi_out(beside(o.output, "_phi.csv"), o.force),
      points_out(beside(o.output, "_points.csv"), o.force),
      constants_out(beside(o.output, "_constants.csv"), o.force);
  FlowCurveTable table = read_flow_curve_table(CsvTable::read(o.table));
  if (!o.structure.empty()) merge_structure(table, CsvTable::read(o.structure));
  std::vector<PackingRun> runs;
  if (!o.packings.empty()) runs = read_packing_runs(CsvTable::read(o.packings));
  if (!o.rates.everything()) keep_rates(o.rates, table, runs);
  const Sweep sweep = make_sweep(table);
  const std::unique_ptr<Resampler> resampler =
      o.packings.empty() ? make_parametric_resampler(sweep)
                         : make_packing_resampler(sweep, runs, o.packings.string());
  Progress bar("bootstrap", static_cast<double>(o.replicates), o.quiet);
  const SweepAnalysis a =
      analyse_sweep(sweep, *resampler, {o.replicates, o.seed},
                    [&](std::size_t done) { bar.update(static_cast<double>(done)); });
  bar.finish();
  print_fit_report(a, o.table.string());
  std::optional<AmplitudeSweepLaw> amplitude_sweep;
  if (!o.oscillation.empty()) {
    amplitude_sweep = make_amplitude_sweep_law(
        read_oscillation_table(CsvTable::read(o.oscillation)), o.oscillation_frequency);
  }

  std::vector<std::string> lines =
      provenance("softglass bridge fit: the flow laws of a particle-engine sweep", command_line);
  const std::size_t quasi_static = sweep.quasi_static_points();
  lines.push_back(fmt::format(
      "input:    {} ({} state points{}, {} volume fractions){}{}", o.table.string(), sweep.points(),
      quasi_static > 0 ? fmt::format(" and {} quasi-static (gamma~ = 0), not fitted", quasi_static)
                       : "",
      sweep.groups.size(), o.packings.empty() ? "" : ", runs " + o.packings.string(),
      o.structure.empty() ? "" : ", structure " + o.structure.string()));
  if (!o.rates.everything())
    lines.push_back(fmt::format("rates:    only gamma~ = {:g} ... {:g} fitted", o.rates.lowest,
                                o.rates.highest));
  for (const std::string& c : table.comments) lines.push_back("input |   " + c);
  lines.push_back("errors:   " + a.method);
  for (const std::string& w : a.warnings) lines.push_back("WARNING:  " + w);
  Law law = make_law(a, lines);
  if (amplitude_sweep) {
    law.provenance.push_back(fmt::format("amplitude sweep: {} at omega~ = {:.6g}",
                                         o.oscillation.string(), amplitude_sweep->frequency));
    law.amplitude_sweep = std::move(amplitude_sweep);
    print_amplitude_sweep_report(law);
  }
  write(law_out, law_text(law));
  write(phi_out, phi_table(a, lines));
  write(points_out, points_table(a, lines));
  write(constants_out, constants_table(a, lines));
  AtomicOutput::commit_together({&law_out, &phi_out, &points_out, &constants_out});
  for (const AtomicOutput* out : {&law_out, &phi_out, &points_out, &constants_out})
    fmt::print("written  {}\n", out->final_path().string());
}

namespace {

// `bridge material --tabulated`: the simulated flow curve in the mode the
// inputs call for (bridge/material/prediction.h), its mode and notes in the
// provenance.
void write_tabulated_material(const MaterialOptions& o, const Law& law,
                              std::vector<std::string> lines, std::optional<AtomicOutput>& out) {
  const PredictionInputs in =
      prediction_inputs(o.source, o.mode, o.phi, o.viscosity, o.extrapolate, lines);
  const SimulatedCurves curves = read_simulated_curves(o.law, law);
  const PredictionScales scales = prediction_scales(law, curves, in);
  lines.push_back("mode:     " + mode_name(scales.mode));
  for (const std::string& note : scales.notes) lines.push_back("          " + note);
  const std::string text =
      tabulated_material_text(tabulated_material_in_mode(law, curves, in, scales), lines);
  if (!out) {
    fmt::print("{}", text);
    return;
  }
  fmt::print("mode     {}\n", mode_name(scales.mode));
  for (const std::string& note : scales.notes) fmt::print("         {}\n", note);
  write(*out, text);
  out->commit();
  fmt::print("written  {}\n", out->final_path().string());
}

}  // namespace

void material_command(const MaterialOptions& o, const std::string& command_line) {
  std::optional<AtomicOutput> out;
  if (!o.output.empty()) out.emplace(o.output, o.force);
  const Law law = read_law_file(o.law);
  std::vector<std::string> lines =
      provenance(o.tabulated
                     ? "softglass bridge material: the simulated flow curve, tabulated, from a law "
                       "file"
                     : "softglass bridge material: a Herschel-Bulkley material from a law file",
                 command_line);
  lines.push_back("law:      " + o.law.string());
  if (o.tabulated) {
    write_tabulated_material(o, law, lines, out);
    return;
  }
  require(!o.mode.yield_stress && o.mode.fit_to.empty(),
          "modes (c) and (d) (--yield-stress, --fit-to) write the simulated flow curve itself: "
          "add --tabulated");
  MaterialRequest request{o.phi, 0.0, o.viscosity, o.extrapolate};
  request.modulus = contact_modulus(o.source, law, o.phi, o.extrapolate, lines);
  const std::string mode = mode_name(o.source.plateau_modulus ? PredictionMode::plateau_modulus
                                                             : PredictionMode::nothing_fitted);
  lines.push_back("mode:     " + mode);
  Material material = make_material(law, request);
  material.source = mode;
  std::optional<AmplitudeSweepPrediction> sweep;
  std::vector<std::string> frequency_lines;
  if (sweep_covers(law, o.phi)) {
    const AmplitudeSweepPrediction& p = sweep.emplace(predict_amplitude_sweep(law, request));
    lines.push_back(fmt::format(
        "amplitude sweep at omega = {:.4g} rad/s: G' plateau {:.4g} Pa, G'' {:.4g} Pa at gamma0 = "
        "{:.3g}; softening strain {:.4g}, crossover strain {:.4g} (0: not reached); `bridge "
        "amplitude-sweep` gives the whole sweep",
        p.angular_frequency, p.plateau_storage.value, p.plateau_loss.value, p.amplitudes.front(),
        p.softening_strain.value, p.crossover_strain.value));
    if (o.frequency)
      frequency_lines.push_back(fmt::format(
          "asked for omega = {:.4g} rad/s: the law's amplitude sweep holds at {:.4g} rad/s for this "
          "E* and eta_s (ratio {:.3g}); run `micro oscillate` at omega~ = {:.4g} for yours",
          *o.frequency, p.angular_frequency, p.angular_frequency / *o.frequency,
          *o.frequency * o.viscosity / request.modulus));
  }
  if (o.frequency) {
    // From the flow law alone, with or without a simulated sweep.
    const double yield_strain = interpolate_value(law.phi, law.yield_strain, o.phi).value;
    const double k = law.k[index(Quantity::sigma)]->value;  // every law has k
    const double omega_tilde = *o.frequency * o.viscosity / request.modulus;
    frequency_lines.push_back(fmt::format(
        "crossover strain estimate at omega = {:.4g} rad/s: {:.3g} (an elastic-perfectly-plastic "
        "loop, G' = G'' at {:.3f} times the strain of the flow stress at the peak rate; "
        "gamma_y = {:.4g}, k = {:.3g}, omega~ = {:.3g}; docs/oscillation.md)",
        *o.frequency, crossover_strain_estimate(yield_strain, k, omega_tilde),
        elastoplastic_crossover_ratio(), yield_strain, k, omega_tilde));
  }
  lines.insert(lines.end(), frequency_lines.begin(), frequency_lines.end());
  const std::string text = material_text(material, lines);
  if (!out) {
    fmt::print("{}", text);
    return;
  }
  print_material_report(material);
  if (sweep) print_amplitude_sweep_prediction(*sweep);
  for (const std::string& line : frequency_lines) fmt::print("{}\n", line);
  write(*out, text);
  out->commit();
  fmt::print("written  {}\n", out->final_path().string());
}

void rescale_command(const RescaleOptions& o, const std::string& command_line) {
  AtomicOutput points_out(o.output, o.force), curves_out(beside(o.output, "_curves.csv"), o.force);
  const MeasuredFile data = read_measured_file(o.data, o.units.format);
  const std::vector<MeasuredCurve> curves = read_measured_curves(data, o.units);
  RescaleSettings settings = o.settings;
  std::string constants = "the paper's values";
  std::optional<Law> law;
  if (!o.law.empty()) {
    law = read_law_file(o.law);
    settings.k = law->k[index(Quantity::sigma)]->value;
    if (law->k[index(Quantity::N1)]) settings.k_N1 = law->k[index(Quantity::N1)]->value;
    constants = "from " + o.law.string();
  }
  if (!o.phi.empty() || o.phi_from_labels) {
    require(law.has_value(), "yield strains from a law (--phi, --phi-from-labels) need --law");
    require(settings.yield_strain.empty() && settings.shear_modulus.empty(),
            "the yield strains come from the law (--phi, --phi-from-labels): give neither "
            "--yield-strain nor --shear-modulus");
    std::vector<double> phi = o.phi;
    if (o.phi_from_labels) {
      std::vector<std::string> labels;
      for (const MeasuredCurve& c : curves) labels.push_back(c.label);
      phi = phi_from_labels(labels);
    }
    require(phi.size() == curves.size(),
            fmt::format("--phi has {} values for {} curves: give one per curve", phi.size(),
                        curves.size()));
    settings.yield_strain = law_yield_strains(*law, phi, o.extrapolate, o.law.string());
    constants += fmt::format("; yield strains from the law at phi = {}", fmt::join(phi, ", "));
  }
  const std::vector<RescaledCurve> rescaled = rescale(curves, settings);
  print_rescale_report(rescaled, settings, constants);

  std::vector<std::string> lines = provenance(
      "softglass bridge rescale: measured flow curves on the universal law", command_line);
  lines.push_back("input:    " + o.data.string());
  lines.push_back("constants: " + constants);
  write(points_out, rescaled_points_table(curves, rescaled, lines));
  write(curves_out, rescaled_curves_table(rescaled, settings, lines));
  AtomicOutput::commit_together({&points_out, &curves_out});
  for (const AtomicOutput* out : {&points_out, &curves_out})
    fmt::print("written  {}\n", out->final_path().string());
}

}  // namespace softglass::bridge
