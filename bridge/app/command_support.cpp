#include "bridge/app/command_support.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <ctime>

#include "bridge/material/amplitude_sweep_prediction.h"
#include "bridge/material/material.h"
#include "common/errors.h"
#include "common/version.h"

namespace softglass::bridge {

std::vector<std::string> provenance(const std::string& title, const std::string& command_line) {
  return {title, "command:  " + command_line,
          fmt::format("software: softglass {} ({}), {:%Y-%m-%d %H:%M:%S} UTC", kVersion,
                      kGitRevision, fmt::gmtime(std::time(nullptr)))};
}

void write(AtomicOutput& out, const std::string& text) {
  write_file(out.temporary_path(), out.final_path().string(), [&](std::ostream& f) { f << text; });
}

bool sweep_covers(const Law& law, double phi) {
  if (!law.amplitude_sweep) return false;
  const std::vector<double>& p = law.amplitude_sweep->phi;
  return phi >= p.front() - 1e-9 && phi <= p.back() + 1e-9;
}

double contact_modulus(const ModulusSource& s, const Law& law, double phi, bool extrapolate,
                       std::vector<std::string>& lines) {
  if (s.modulus) return *s.modulus;
  if (s.plateau_modulus) {
    const bool oscillatory = s.plateau_source == "amplitude-sweep";
    const MaterialValue e_star =
        oscillatory
            ? contact_modulus_from_amplitude_sweep(law, phi, *s.plateau_modulus, extrapolate)
            : contact_modulus_from_plateau(law, phi, *s.plateau_modulus, extrapolate);
    const std::string ratio =
        oscillatory
            ? fmt::format("(G' plateau/E*)(phi), the law's amplitude sweep at omega~ = {:.4g}",
                          law.amplitude_sweep->frequency)
            : std::string("(G0/E*)(phi), the law's static G0");
    fmt::print("E*       {:.6g} Pa {} = G' / {}: every stress below carries this error too\n",
               e_star.value, relative_error_text(e_star), ratio);
    lines.push_back(fmt::format(
        "E* = G' / {} = {:.6g} Pa / {:.6g} = {:.6g} Pa {} (every stress below scales with E*, so "
        "this error adds to theirs)",
        ratio, *s.plateau_modulus, *s.plateau_modulus / e_star.value, e_star.value,
        relative_error_text(e_star)));
    return e_star.value;
  }
  return emulsion_modulus(s, lines);
}

double emulsion_modulus(const ModulusSource& s, std::vector<std::string>& lines) {
  const double e_star = emulsion_contact_modulus(*s.interfacial_tension, *s.radius);
  lines.push_back(fmt::format(
      "E* = 9.92 gamma_i / R = 9.92 x {:.6g} N/m / {:.6g} m = {:.6g} Pa (Seth et al. 2006, "
      "emulsions)",
      *s.interfacial_tension, *s.radius, e_star));
  return e_star;
}

PredictionInputs prediction_inputs(const ModulusSource& source, const ModeInputs& mode,
                                   double phi, double viscosity, bool extrapolate,
                                   std::vector<std::string>& lines) {
  require(source.plateau_source == "static",
          "the prediction modes take E* from the law's static G0 (mode b); --plateau-source "
          "amplitude-sweep is for the Herschel-Bulkley material");
  PredictionInputs in;
  in.phi = phi;
  in.viscosity = viscosity;
  in.extrapolate = extrapolate;
  in.modulus = source.interfacial_tension ? emulsion_modulus(source, lines) : source.modulus;
  in.plateau_modulus = source.plateau_modulus;
  in.yield_stress = mode.yield_stress;
  if (!mode.fit_to.empty()) in.measured_curve = measured_curve(mode.fit_to, mode.fit_curve, mode.units);
  return in;
}

}  // namespace softglass::bridge
