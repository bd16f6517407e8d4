#include "bridge/app/commands.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <ctime>

#include "bridge/app/law_file.h"
#include "bridge/app/report.h"
#include "bridge/law/law.h"
#include "bridge/material/material.h"
#include "bridge/output/tables.h"
#include "bridge/rescale/law_yield_strain.h"
#include "bridge/sweep/analysis.h"
#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/progress.h"
#include "common/version.h"

namespace softglass::bridge {

namespace {

std::vector<std::string> provenance(const std::string& title, const std::string& command_line) {
  return {title, "command:  " + command_line,
          fmt::format("software: softglass {} ({}), {:%Y-%m-%d %H:%M:%S} UTC", kVersion,
                      kGitRevision, fmt::gmtime(std::time(nullptr)))};
}

// A result file beside `main`: law.prm → law_phi.csv.
std::filesystem::path beside(const std::filesystem::path& main, const std::string& suffix) {
  return main.parent_path() / (main.stem().string() + suffix);
}

void write(AtomicOutput& out, const std::string& text) {
  write_file(out.temporary_path(), out.final_path().string(),
                  [&](std::ostream& f) { f << text; });
}

}  // namespace

void fit_command(const FitOptions& o, const std::string& command_line) {
  // Refuse early, before any work, if a result exists.
  AtomicOutput law_out(o.output, o.force), phi_out(beside(o.output, "_phi.csv"), o.force),
      points_out(beside(o.output, "_points.csv"), o.force),
      constants_out(beside(o.output, "_constants.csv"), o.force);
  FlowCurveTable table = read_flow_curve_table(CsvTable::read(o.table));
  if (!o.structure.empty()) merge_structure(table, CsvTable::read(o.structure));
  const Sweep sweep = make_sweep(table);
  const std::unique_ptr<Resampler> resampler =
      o.packings.empty()
          ? make_parametric_resampler(sweep)
          : make_packing_resampler(sweep, read_packing_runs(CsvTable::read(o.packings)),
                                   o.packings.string());
  Progress bar("bootstrap", static_cast<double>(o.replicates), o.quiet);
  const SweepAnalysis a =
      analyse_sweep(sweep, *resampler, {o.replicates, o.seed},
                    [&](std::size_t done) { bar.update(static_cast<double>(done)); });
  bar.finish();
  print_fit_report(a, o.table.string());

  std::vector<std::string> lines =
      provenance("softglass bridge fit: the flow laws of a particle-engine sweep", command_line);
  const std::size_t quasi_static = sweep.quasi_static_points();
  lines.push_back(fmt::format(
      "input:    {} ({} state points{}, {} volume fractions){}{}", o.table.string(), sweep.points(),
      quasi_static > 0 ? fmt::format(" and {} quasi-static (gamma~ = 0), not fitted", quasi_static)
                       : "",
      sweep.groups.size(), o.packings.empty() ? "" : ", runs " + o.packings.string(),
      o.structure.empty() ? "" : ", structure " + o.structure.string()));
  for (const std::string& c : table.comments) lines.push_back("input |   " + c);
  lines.push_back("errors:   " + a.method);
  for (const std::string& w : a.warnings) lines.push_back("WARNING:  " + w);
  write(law_out, law_text(make_law(a, lines)));
  write(phi_out, phi_table(a, lines));
  write(points_out, points_table(a, lines));
  write(constants_out, constants_table(a, lines));
  AtomicOutput::commit_together({&law_out, &phi_out, &points_out, &constants_out});
  for (const AtomicOutput* out : {&law_out, &phi_out, &points_out, &constants_out})
    fmt::print("written  {}\n", out->final_path().string());
}

void material_command(const MaterialOptions& o, const std::string& command_line) {
  std::optional<AtomicOutput> out;
  if (!o.output.empty()) out.emplace(o.output, o.force);
  const Law law = read_law_file(o.law);
  MaterialRequest request{o.phi, 0.0, o.viscosity, o.extrapolate};
  std::vector<std::string> lines = provenance(
      "softglass bridge material: a Herschel-Bulkley material from a law file", command_line);
  lines.push_back("law:      " + o.law.string());
  if (o.modulus) {
    request.modulus = *o.modulus;
  } else if (o.plateau_modulus) {
    const MaterialValue e_star =
        contact_modulus_from_plateau(law, o.phi, *o.plateau_modulus, o.extrapolate);
    request.modulus = e_star.value;
    fmt::print(
        "E*       {:.6g} Pa ± {:.2g} % = G' / (G0/E*)(phi): every stress below carries this "
        "error too\n",
        e_star.value, 100.0 * e_star.error() / e_star.value);
    lines.push_back(fmt::format(
        "E* = G' / (G0/E*)(phi) = {:.6g} Pa / {:.6g} = {:.6g} Pa +- {:.2g} % (the law's G0/E* at "
        "phi; every stress below scales with E*, so this error adds to theirs)",
        *o.plateau_modulus, *o.plateau_modulus / e_star.value, e_star.value,
        100.0 * e_star.error() / e_star.value));
  } else {
    require(*o.interfacial_tension > 0 && *o.radius > 0,
            "the interfacial tension and the radius must be positive");
    request.modulus = 9.92 * *o.interfacial_tension / *o.radius;
    lines.push_back(
        fmt::format("E* = 9.92 gamma_i / R = 9.92 x {:.6g} N/m / {:.6g} m (Seth et al. "
                    "2006, emulsions)",
                    *o.interfacial_tension, *o.radius));
  }
  const Material material = make_material(law, request);
  const std::string text = material_text(material, lines);
  if (!out) {
    fmt::print("{}", text);
    return;
  }
  print_material_report(material);
  write(*out, text);
  out->commit();
  fmt::print("written  {}\n", out->final_path().string());
}

void rescale_command(const RescaleOptions& o, const std::string& command_line) {
  AtomicOutput points_out(o.output, o.force), curves_out(beside(o.output, "_curves.csv"), o.force);
  const CsvTable csv = CsvTable::read(o.data);
  const std::vector<MeasuredCurve> curves = read_measured_curves(csv, o.units);
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
