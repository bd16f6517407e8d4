#include "bridge/material/material.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bridge/material/interpolation.h"
#include "common/errors.h"
#include "common/si_range.h"

namespace softglass::bridge {

double MaterialValue::error() const {
  return std::isnan(interpolation) ? statistical : std::hypot(statistical, interpolation);
}

std::string relative_error_text(const MaterialValue& v) {
  if (std::isnan(v.statistical)) return "+- n/a (one packing: no scatter between packings)";
  return fmt::format("+- {:.2g} %", 100.0 * v.error() / std::abs(v.value));
}

namespace {

MaterialLaw dimensional(const Law& law, const HbLaw& hb, const MaterialRequest& request) {
  const double e_star = request.modulus;
  const double log_time = std::log(request.viscosity / e_star);  // L = ln(η_s/E*)
  std::vector<Estimate> yield, consistency;
  for (std::size_t j = 0; j < law.phi.size(); ++j) {
    yield.push_back({e_star * hb.yield[j].value, e_star * hb.yield[j].error});
    const Estimate& k = hb.consistency[j];
    const Estimate& m = hb.exponent[j];
    const double rel_k = k.error / std::abs(k.value);
    const double variance = rel_k * rel_k + log_time * log_time * m.error * m.error +
                            2.0 * log_time * hb.correlation[j] * rel_k * m.error;
    const double value = e_star * k.value * std::exp(m.value * log_time);
    consistency.push_back({value, std::abs(value) * std::sqrt(std::max(variance, 0.0))});
  }
  return {interpolate_value(law.phi, yield, request.phi),
          interpolate_value(law.phi, consistency, request.phi),
          interpolate_value(law.phi, hb.exponent, request.phi)};
}


}  // namespace

MaterialValue interpolate_value(const std::vector<double>& phi, const std::vector<Estimate>& v,
                                double at) {
  const bool positive =
      std::all_of(v.begin(), v.end(), [](const Estimate& e) { return e.value > 0; });
  const bool negative =
      std::all_of(v.begin(), v.end(), [](const Estimate& e) { return e.value < 0; });
  if (!positive && !negative) {
    const Interpolated r = interpolate(phi, v, at);
    return {r.value, r.statistical, r.interpolation};
  }
  std::vector<Estimate> logs;
  for (const Estimate& e : v)
    logs.push_back({std::log(std::abs(e.value)), e.error / std::abs(e.value)});
  const Interpolated r = interpolate(phi, logs, at);
  const double value = (positive ? 1.0 : -1.0) * std::exp(r.value);
  return {value, std::abs(value) * r.statistical, std::abs(value) * r.interpolation};
}

void check_phi(const std::vector<double>& p, double phi, bool extrapolate) {
  require(phi > 0 && phi < 1, fmt::format("volume fraction phi = {} must be in (0, 1)", phi));
  if (is_simulated(p, phi)) return;
  require(p.size() >= 2, fmt::format("the law holds for phi = {} only (one simulated volume "
                                     "fraction); phi = {} cannot be reached",
                                     p.front(), phi));
  require(extrapolate || (phi >= p.front() && phi <= p.back()),
          fmt::format("phi = {} is outside the simulated range {} ... {}; pass --extrapolate "
                      "to extrapolate linearly (its error then assumes the curvature seen "
                      "inside the range)",
                      phi, p.front(), p.back()));
}

double emulsion_contact_modulus(double interfacial_tension, double radius) {
  require(interfacial_tension > 0 && radius > 0,
          "the interfacial tension and the radius must be positive");
  return 9.92 * interfacial_tension / radius;
}

MaterialValue contact_modulus_from_plateau(const Law& law, double phi, double plateau_modulus,
                                           bool extrapolate) {
  require(plateau_modulus > 0 && std::isfinite(plateau_modulus),
          fmt::format("plateau modulus G' = {} Pa must be positive", plateau_modulus));
  check_phi(law.phi, phi, extrapolate);
  const MaterialValue g0 = interpolate_value(law.phi, law.modulus, phi);
  require(g0.value > 0, fmt::format("the law's G0/E* at phi = {} is {:.3g}: no solid to scale "
                                    "a plateau modulus by",
                                    phi, g0.value));
  const double e_star = plateau_modulus / g0.value;
  return {e_star, e_star * g0.statistical / g0.value, e_star * g0.interpolation / g0.value};
}

std::string describe_placement(const Law& law, double phi) {
  const std::vector<double>& p = law.phi;
  if (is_simulated(p, phi)) return fmt::format("at the simulated volume fraction {}", phi);
  if (phi < p.front() || phi > p.back()) {
    return fmt::format("EXTRAPOLATED from the simulated range {} ... {}", p.front(), p.back());
  }
  const auto above = std::upper_bound(p.begin(), p.end(), phi);
  return fmt::format("interpolated between the simulated volume fractions {} and {}", *(above - 1),
                     *above);
}

void check_request(const Law& law, const MaterialRequest& request) {
  require(request.modulus > 0 && within_si_range(request.modulus),
          fmt::format("contact modulus E* = {} Pa must be positive, between {:g} and {:g}",
                      request.modulus, 1 / kSiRange, kSiRange));
  require(request.viscosity > 0 && within_si_range(request.viscosity),
          fmt::format("solvent viscosity eta_s = {} Pa s must be positive, between {:g} and {:g}",
                      request.viscosity, 1 / kSiRange, kSiRange));
  check_phi(law.phi, request.phi, request.extrapolate);
}

Material make_material(const Law& law, const MaterialRequest& request) {
  check_request(law, request);

  Material m;
  m.request = request;
  m.placement = describe_placement(law, request.phi);
  m.rate_min = law.gamma_tilde_min * request.modulus / request.viscosity;
  m.rate_max = law.gamma_tilde_max * request.modulus / request.viscosity;
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
    if (!law.hb[index(q)]) continue;
    const MaterialLaw& result =
        m.laws[index(q)].emplace(dimensional(law, *law.hb[index(q)], request));
    const double n = result.index.value;
    require(n > 0 && n <= 2,
            fmt::format("the {} flow index at phi = {} comes out as {:.3g}, outside (0, 2]",
                        column_name(q), request.phi, n));
  }
  // Every number the material file will hold must be one macro accepts
  // (common/si_range.h): an extreme E* or eta_s scales the reduced law to
  // values (K = 1e-141 Pa s^n at E* = 1e-300 Pa) that would be written with
  // exit 0 and refused only later by macro.
  const auto finite = [&](const MaterialValue& v, Quantity q, const char* name) {
    require(within_si_range(v.value) && std::isfinite(v.error()),
            fmt::format("the {} {} at phi = {} comes out as {:.3g} +- {:.3g}, outside 0 or "
                        "magnitudes 1e-100 ... 1e100 (SI) that macro solves with: E* = {:.3g} Pa "
                        "and eta_s = {:.3g} Pa s are beyond what the law can be scaled to",
                        column_name(q), name, request.phi, v.value, v.error(), request.modulus,
                        request.viscosity));
  };
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
    if (!m.laws[index(q)]) continue;
    finite(m.laws[index(q)]->yield, q, "yield stress");
    finite(m.laws[index(q)]->consistency, q, "consistency");
    finite(m.laws[index(q)]->index, q, "flow index");
  }
  require(std::isfinite(m.rate_min) && std::isfinite(m.rate_max) && m.rate_min > 0,
          fmt::format("the law's shear rates at E* = {:.3g} Pa, eta_s = {:.3g} Pa s come out as "
                      "{:.3g} ... {:.3g} 1/s, not finite and positive",
                      request.modulus, request.viscosity, m.rate_min, m.rate_max));
  const MaterialLaw& shear = *m.laws[index(Quantity::sigma)];
  require(shear.yield.value >= 0 && shear.consistency.value > 0,
          fmt::format("the shear law at phi = {} comes out with tau_y = {:.3g} Pa, K = {:.3g}: "
                      "not a Herschel-Bulkley material",
                      request.phi, shear.yield.value, shear.consistency.value));
  return m;
}

std::string error_comment(const std::string& name, const MaterialValue& v, const char* units) {
  const double scale = std::abs(v.value) > 0 ? 100.0 / std::abs(v.value) : 0.0;
  const std::string interpolation = std::isnan(v.interpolation)
                                        ? "unknown (two volume fractions)"
                                        : fmt::format("{:.2g} %", scale * v.interpolation);
  return fmt::format(
      "#   {:<12} = {:.6g}{}{} +- {:.2g} % (statistical {:.2g} %, interpolation {})\n", name,
      v.value, *units ? " " : "", units, scale * v.error(), scale * v.statistical, interpolation);
}

std::string material_text(const Material& m, const std::vector<std::string>& provenance) {
  std::string out;
  for (const std::string& line : provenance) out += "# " + line + "\n";
  out += fmt::format(
      "# phi = {}, E* = {:.6g} Pa, eta_s = {:.6g} Pa s: {}\n"
      "# valid for shear rates {:.3g} ... {:.3g} 1/s (the simulated range of gamma~)\n"
      "# errors (one standard deviation):\n",
      m.request.phi, m.request.modulus, m.request.viscosity, m.placement, m.rate_min, m.rate_max);
  const MaterialLaw& shear = *m.laws[index(Quantity::sigma)];
  out += error_comment("tau_y", shear.yield, "Pa");
  out += error_comment("K", shear.consistency, "Pa s^n");
  out += error_comment("n", shear.index, "");
  for (Quantity q : {Quantity::N1, Quantity::N2}) {
    if (const auto& n = m.laws[index(q)]) {
      const std::string name = column_name(q);
      out += error_comment(name + " yield", n->yield, "Pa");
      out += error_comment(name + " K", n->consistency, "Pa s^n");
      out += error_comment(name + " n", n->index, "");
    }
  }
  const auto line = [&](const std::string& name, const std::string& value,
                        const std::string& note) {
    out += fmt::format("  set {:<17} = {:<18} # {}\n", name, value, note);
  };
  const auto number = [](const MaterialValue& v) { return fmt::format("{:.6g}", v.value); };
  out +=
      "subsection material\n"
      "  # Shear stress: tau = tau_y + K gamma_dot^n above the yield stress.\n";
  line("model", "herschel-bulkley", "herschel-bulkley | bingham | power-law | newtonian");
  if (!m.source.empty()) line("source", m.source, "how E* was set (docs/bridge.md)");
  line("yield stress", number(shear.yield), "tau_y [Pa]");
  line("consistency", number(shear.consistency), "K [Pa s^n]");
  line("flow index", number(shear.index), "n [1]");
  if (m.laws[index(Quantity::N1)] || m.laws[index(Quantity::N2)]) {
    out += "  # Normal stress differences: N = N_y + K_N gamma_dot^n_N (zero if absent).\n";
  }
  for (Quantity q : {Quantity::N1, Quantity::N2}) {
    if (const auto& n = m.laws[index(q)]) {
      const std::string name = column_name(q);
      line(name + " yield", number(n->yield), "[Pa]");
      line(name + " consistency", number(n->consistency), "[Pa s^n_" + name + "]");
      line(name + " flow index", number(n->index), "[1]");
    }
  }
  out += "end\n";
  return out;
}

}  // namespace softglass::bridge
