// `bridge predict`: the predicted flow curve at a user's rates, in one of the
// four modes of bridge/material/prediction.h, as a CSV to overlay on measured
// data (shear rate and shear stress first, then N1, N2, the bands and the
// extrapolation flag).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <sstream>

#include "bridge/app/command_support.h"
#include "bridge/app/commands.h"
#include "bridge/app/law_file.h"
#include "bridge/material/prediction.h"
#include "common/command_line.h"
#include "common/csv_table.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

// --rates: a comma-separated list of numbers, or a measured file's rates.
std::vector<double> requested_rates(const PredictOptions& o) {
  std::vector<double> rates;
  std::istringstream in(o.rates);
  std::string item;
  bool numbers = true;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      rates.push_back(std::stod(item, &used));
      numbers = numbers && item.find_first_not_of(" \t", used) == std::string::npos;
    } catch (const std::exception&) {
      numbers = false;
    }
  }
  if (numbers && !rates.empty()) return rates;
  require(std::filesystem::exists(o.rates),
          fmt::format("--rates {}: neither a list of numbers nor a file", o.rates));
  return measured_curve(o.rates, o.curve, o.mode.units).shear_rate;
}

}  // namespace

MeasuredCurve measured_curve(const std::filesystem::path& file, const std::string& label,
                             const MeasuredReading& units) {
  const std::vector<MeasuredCurve> curves =
      read_measured_curves(read_measured_file(file, units.format), units);
  if (label.empty()) {
    require(curves.size() == 1,
            fmt::format("{} holds {} curves: name one with --curve", file.string(), curves.size()));
    return curves.front();
  }
  for (const MeasuredCurve& c : curves)
    if (c.label == label) return c;
  std::vector<std::string> labels;
  for (const MeasuredCurve& c : curves) labels.push_back(c.label);
  throw InputError(fmt::format("{} has no curve '{}'; it has: {}", file.string(), label,
                               fmt::join(labels, ", ")));
}

CLI::App* add_predict_command(CLI::App& app, PredictOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "predict",
      "the predicted flow curve (shear stress, N1, N2 with their bands) at given shear rates, "
      "in one of four modes: (a) E* given, (b) E* from a measured G', (c) a measured yield "
      "stress, (d) E* fitted to a measured flow curve");
  cmd->add_option("law", o.law, "law file of `bridge fit` (.prm), its _points.csv beside it")
      ->required();
  cmd->add_option("--phi", o.phi, "volume fraction")->required()->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--viscosity", o.viscosity, "solvent viscosity eta_s [Pa s]")
      ->required()
      ->check(positive);
  auto* modulus = cmd->add_option("--modulus", o.source.modulus, "contact modulus E* [Pa]")->check(positive);
  auto* tension = cmd->add_option("--interfacial-tension", o.source.interfacial_tension,
                                  "emulsions: gamma_i [N/m], with --radius: E* = 9.92 gamma_i / R")
                      ->check(positive);
  auto* radius = cmd->add_option("--radius", o.source.radius, "mean droplet radius R [m]")->check(positive);
  auto* plateau = cmd->add_option("--plateau-modulus", o.source.plateau_modulus,
                                  "measured linear shear modulus G' [Pa]: E* = G'/(G0/E*)(phi) "
                                  "(mode b; with --yield-stress, mode c)")
                      ->check(positive);
  cmd->add_option("--yield-stress", o.mode.yield_stress,
                  "measured yield stress [Pa] (mode c: the model gives the rate dependence and "
                  "the normal stresses)")
      ->check(positive);
  auto* fit = cmd->add_option("--fit-to", o.mode.fit_to,
                              "a measured flow curve (CSV) to fit E* to (mode d)");
  cmd->add_option("--fit-curve", o.mode.fit_curve, "the curve of --fit-to's file, by its label");
  cmd->add_option("--rates", o.rates,
                  "shear rates [1/s]: a comma-separated list, or a measured file whose rates "
                  "to predict at")
      ->required();
  cmd->add_option("--curve", o.curve, "the curve of --rates' file, by its label");
  add_measured_format_option(*cmd, o.mode.units.format, "--fit-to's and --rates' measured files");
  cmd->add_option("--rate-unit", o.mode.units.rate, "units of rate columns without units");
  cmd->add_option("--stress-unit", o.mode.units.stress, "units of stress columns without units");
  cmd->add_option("--law-form", o.form,
                  "tabulated (the simulated flow curve itself) or herschel-bulkley (its fitted "
                  "summary, to compare)")
      ->check(CLI::IsMember({"tabulated", "herschel-bulkley"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", o.output, "the prediction (CSV); default: print it");
  cmd->add_flag("--extrapolate", o.extrapolate,
                "allow phi outside the simulated range (linear extrapolation)");
  cmd->add_flag("-f,--force", o.force, "overwrite an existing output");
  tension->needs(radius);
  radius->needs(tension);
  modulus->excludes(tension);
  plateau->excludes(modulus);
  plateau->excludes(tension);
  fit->excludes(modulus);
  fit->excludes(plateau);
  fit->excludes(tension);
  return cmd;
}

void predict_command(const PredictOptions& o, const std::string& command_line) {
  std::optional<AtomicOutput> out;
  if (!o.output.empty()) out.emplace(o.output, o.force);
  const Law law = read_law_file(o.law);
  std::vector<std::string> lines =
      provenance("softglass bridge predict: a flow curve from a law file", command_line);
  lines.push_back("law:      " + o.law.string());
  PredictionInputs in =
      prediction_inputs(o.source, o.mode, o.phi, o.viscosity, o.extrapolate, lines);
  in.form = o.form == "tabulated" ? LawForm::tabulated : LawForm::herschel_bulkley;
  in.model_error = read_model_error(o.law);
  lines.push_back(fmt::format("phi = {}, eta_s = {:.6g} Pa s", o.phi, o.viscosity));
  const Prediction p = predict(law, read_simulated_curves(o.law, law), in, requested_rates(o));
  const std::string text = prediction_table(p, lines);
  if (!out) {
    fmt::print("{}", text);
    return;
  }
  fmt::print("mode     {}\n", mode_name(p.mode));
  for (const std::string& note : p.notes) fmt::print("         {}\n", note);
  const auto outside = std::count_if(p.points.begin(), p.points.end(),
                                     [](const PredictedPoint& q) { return q.extrapolated; });
  if (outside > 0)
    fmt::print("         {} of {} rates outside the simulated window: extrapolated (flagged)\n",
               outside, p.points.size());
  write(*out, text);
  out->commit();
  fmt::print("written  {}\n", out->final_path().string());
}

}  // namespace softglass::bridge
