#include "bridge/app/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bridge/law/law.h"

namespace softglass::bridge {

// Relative errors below this are noise (the integrators' tolerances are 1e-3 …
// 1e-6 of a step's displacement; repeated deterministic cycles agree to 1e-10).
constexpr double kNoiseLevel = 1e-8;

std::string with_error(double value, double error, int digits, const std::string& unit) {
  if (!std::isfinite(value)) return "not fitted";
  const std::string u = unit.empty() ? "" : " " + unit;
  // No error, or only noise: one packing has no packing-to-packing spread, and
  // the cycles of a deterministic (unyielded) oscillation repeat to the
  // solver's tolerance, far below what any digit printed here could show.
  if (!std::isfinite(error) || error <= kNoiseLevel * std::abs(value))
    return fmt::format("{:.4g}{}", value, u);
  // Not one significant digit of the value is known: said in words.
  if (error > std::abs(value))
    return fmt::format("{:.2g}{}, not distinguishable from zero (error {:.{}g}{})", value, u, error,
                       digits, u);
  // Print the value to the decimal place of the error's last significant digit.
  const int place = static_cast<int>(std::floor(std::log10(error))) - (digits - 1);
  const double magnitude = std::max(std::abs(value), error);
  if (magnitude < 1e-3 || magnitude >= 1e5) {
    // As many significant digits of the value as reach the error's last one.
    const int value_digits =
        std::max(1, static_cast<int>(std::floor(std::log10(std::abs(value)))) - place + 1);
    return fmt::format("{:.{}e} ± {:.{}g}{}", value, value_digits - 1, error, digits, u);
  }
  const int decimals = std::max(0, -place);
  return fmt::format("{:.{}f} ± {:.{}f}{}", value, decimals, error, decimals, u);
}

namespace {

// Rheometer data scatter by a few per cent; a law missing them by more than 10 %
// rms does not describe the curve.
constexpr double kPoorCollapse = 0.10;

const char* law_title(Quantity q) {
  switch (q) {
    case Quantity::sigma:
      return "sigma/E* = sigma_y/E* + k_sigma gamma~^m";
    case Quantity::N1:
      return "N1/E* = N1_y/E* + k_N1 gamma~^m";
    case Quantity::N2:
      return "N2/E* = N2_y/E* + k_N2 gamma~^m";
    case Quantity::force:
      return "f_m/(E* R^2) = f_y + k_f gamma~^m (force at maximum accumulation)";
  }
  return "";
}

// The quasi-static σ_y (the table's γ̃ = 0 rows) beside the Herschel–Bulkley
// σ_y: two estimates of one yield stress, and their difference in units of
// its standard error (both errors combined).
void print_quasi_static_yield(const SweepAnalysis& a) {
  fmt::print(
      "\nyield stress: quasi-static (AQS, the gamma~ = 0 rows, not fitted) against "
      "Herschel-Bulkley\n");
  fmt::print("  {:<6} {:>24} {:>24} {:>10}\n", "phi", "AQS sigma_y/E*", "HB sigma_y/E*", "diff/SE");
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const PhiGroup& g = a.sweep.groups[j];
    const double hb = a.estimate.fit.groups[j].hb[index(Quantity::sigma)]->yield;
    const double hb_error = a.uncertainty.error.groups[j].hb[index(Quantity::sigma)]->yield;
    if (!g.quasi_static) {
      fmt::print("  {:<6} {:>24} {:>24}\n", g.phi, "-", with_error(hb, hb_error));
      continue;
    }
    const Estimate aqs = *g.quasi_static->values[index(Quantity::sigma)];
    // Not a number when σ_y was not fitted or neither estimate has an error.
    const double z = (aqs.value - hb) / std::sqrt(aqs.error * aqs.error + hb_error * hb_error);
    fmt::print("  {:<6} {:>24} {:>24} {:>10}\n", g.phi, with_error(aqs.value, aqs.error),
               with_error(hb, hb_error), std::isfinite(z) ? fmt::format("{:.2f}", z) : "-");
  }
}

}  // namespace

void print_fit_report(const SweepAnalysis& a, const std::string& source) {
  const std::vector<PhiGroup>& groups = a.sweep.groups;
  double low = INFINITY, high = 0;
  for (const PhiGroup& g : groups) {
    low = std::min(low, g.curves[index(Quantity::sigma)]->x.front());
    high = std::max(high, g.curves[index(Quantity::sigma)]->x.back());
  }
  const std::size_t quasi_static = a.sweep.quasi_static_points();
  fmt::print(
      "sweep    {}: {} state points, {} volume fractions {} ... {}, gamma~ {:.3g} ... {:.3g}{}\n",
      source, a.sweep.points(), groups.size(), groups.front().phi, groups.back().phi, low, high,
      quasi_static > 0 ? fmt::format("; and {} quasi-static (gamma~ = 0), not fitted", quasi_static)
                       : "");
  fmt::print("errors   one standard deviation from a {}\n", a.method);
  for (Quantity q : kAllQuantities) {
    if (!a.sweep.present[index(q)]) continue;
    fmt::print("\nHerschel-Bulkley per volume fraction: {}\n", law_title(q));
    fmt::print("  {:<6} {:>24} {:>24} {:>16} {:>9} {:>8}\n", "phi", "yield", "consistency",
               "exponent m", "chi2/dof", "p");
    for (std::size_t j = 0; j < groups.size(); ++j) {
      const HbParameters& v = *a.estimate.fit.groups[j].hb[index(q)];
      const HbParameters& e = *a.uncertainty.error.groups[j].hb[index(q)];
      const GoodnessOfFit& g = a.estimate.diagnostics.hb[j][index(q)]->goodness;
      fmt::print("  {:<6} {:>24} {:>24} {:>16} {:>9.2f} {:>8.2g}\n", groups[j].phi,
                 with_error(v.yield, e.yield), with_error(v.consistency, e.consistency),
                 with_error(v.exponent, e.exponent), g.reduced_chi2(), g.p_value);
    }
  }

  fmt::print("\nyield strain gamma_y = sigma_y/G0   (the paper: {} ... {})\n",
             PaperValues::yield_strain_min, PaperValues::yield_strain_max);
  fmt::print("  {:<6} {:>24} {:>20}\n", "phi", "G0/E*", "gamma_y");
  for (std::size_t j = 0; j < groups.size(); ++j) {
    const GroupFit &v = a.estimate.fit.groups[j], &e = a.uncertainty.error.groups[j];
    fmt::print("  {:<6} {:>24} {:>20}\n", groups[j].phi, with_error(v.modulus, e.modulus),
               with_error(v.yield_strain, e.yield_strain));
  }

  if (quasi_static > 0) print_quasi_static_yield(a);

  if (a.sweep.present[index(Quantity::force)]) {
    fmt::print(
        "\nforce law f_m/(E* R^2) = f_y + k_f gamma~^(1/2)   (the paper's Fig. 3c; exponent "
        "0.50 +- 0.02)\n");
    fmt::print("  {:<6} {:>24} {:>24} {:>16}\n", "phi", "f_y", "k_f", "free exponent");
    for (std::size_t j = 0; j < groups.size(); ++j) {
      const GroupFit &v = a.estimate.fit.groups[j], &e = a.uncertainty.error.groups[j];
      fmt::print("  {:<6} {:>24} {:>24} {:>16}\n", groups[j].phi,
                 with_error(*v.force_yield, *e.force_yield),
                 with_error(*v.force_slope, *e.force_slope),
                 with_error(v.hb[index(Quantity::force)]->exponent,
                            e.hb[index(Quantity::force)]->exponent));
    }
  }

  fmt::print(
      "\nuniversal laws, one constant for every volume fraction   this sweep      the paper\n");
  const std::tuple<Quantity, const char*, Estimate> rows[] = {
      {Quantity::sigma, "k    sigma/sigma_y = 1 + k (gamma~/gamma_y^2)^1/2", PaperValues::k},
      {Quantity::N1, "k'   N1/sigma_y    = N1_y/sigma_y + k' (...)^1/2", PaperValues::k_N1},
      {Quantity::N2, "k''  -N2/sigma_y   = -N2_y/sigma_y + k'' (...)^1/2", PaperValues::k_N2}};
  for (const auto& [q, name, paper] : rows) {
    if (!a.estimate.fit.k[index(q)]) continue;
    const auto& collapse = a.collapse[index(q)];
    fmt::print("  {:<53} {:>16} {:>10}{}\n", name,
               with_error(*a.estimate.fit.k[index(q)], *a.uncertainty.error.k[index(q)]),
               with_error(paper.value, paper.error, 1),
               collapse ? fmt::format("   collapse Q/dof = {:.2f}, p = {:.2g}",
                                      collapse->reduced_chi2(), collapse->p_value)
                        : "");
  }
  fmt::print("  {:<53} {:>16} {:>10}\n", "m    mean Herschel-Bulkley exponent of sigma",
             with_error(a.estimate.fit.mean_exponent, a.uncertainty.error.mean_exponent),
             with_error(PaperValues::exponent.value, PaperValues::exponent.error, 1));
  if (!a.warnings.empty()) {
    fmt::print("\nwarnings\n");
    for (const std::string& w : a.warnings) fmt::print("  {}\n", w);
  }
}

void print_material_report(const Material& m) {
  fmt::print("material phi = {}, E* = {:.6g} Pa, eta_s = {:.6g} Pa s: {}\n", m.request.phi,
             m.request.modulus, m.request.viscosity, m.placement);
  fmt::print("         valid for shear rates {:.3g} ... {:.3g} 1/s\n", m.rate_min, m.rate_max);
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
    const auto& law = m.laws[index(q)];
    if (!law) continue;
    const char* lhs = q == Quantity::sigma ? "tau" : column_name(q);
    fmt::print("         {:<3} = {} + {} gamma_dot^n, n = {}\n", lhs,
               with_error(law->yield.value, law->yield.error(), 2, "Pa"),
               with_error(law->consistency.value, law->consistency.error(), 2, "Pa s^n"),
               with_error(law->index.value, law->index.error()));
  }
}

void print_amplitude_sweep_report(const Law& law) {
  const AmplitudeSweepLaw& a = *law.amplitude_sweep;
  fmt::print("\namplitude sweep at omega~ = {:.4g}, gamma0 = {:.3g} ... {:.3g} ({} amplitudes)\n",
             a.frequency, a.amplitudes.front(), a.amplitudes.back(), a.amplitudes.size());
  fmt::print("  {:>6} {:>22} {:>22} {:>22} {:>22} {:>9}\n", "phi", "G' plateau/E*",
             "G'' plateau/E*", "softening strain", "crossover strain", "gamma_y");
  for (std::size_t i = 0; i < a.phi.size(); ++i) {
    const auto j = std::find_if(law.phi.begin(), law.phi.end(),
                                [&](double p) { return std::abs(p - a.phi[i]) < 1e-9; });
    const std::string static_part =
        j == law.phi.end()
            ? ""
            : fmt::format(" (static G0/E* {:.4g})", law.modulus[j - law.phi.begin()].value);
    const auto strain = [](const Estimate& e) {
      return e.value > 0 ? with_error(e.value, e.error) : std::string("not reached");
    };
    fmt::print("  {:>6.3f} {:>22} {:>22} {:>22} {:>22} {:>9}{}\n", a.phi[i],
               with_error(a.plateau_storage[i].value, a.plateau_storage[i].error),
               with_error(a.plateau_loss[i].value, a.plateau_loss[i].error),
               strain(a.softening_strain[i]), strain(a.crossover_strain[i]),
               j == law.phi.end()
                   ? std::string("-")
                   : fmt::format("{:.4f}", law.yield_strain[j - law.phi.begin()].value),
               static_part);
  }
}

void print_amplitude_sweep_prediction(const AmplitudeSweepPrediction& p) {
  const auto strain = [](const MaterialValue& v) {
    return v.value > 0 ? with_error(v.value, v.error()) : std::string("not reached");
  };
  fmt::print(
      "amplitude sweep at omega = {:.4g} rad/s (the law's omega~ = {:.4g}): G' plateau = {} "
      "Pa, G'' = {} Pa (gamma0 = {:.3g}); softening strain {}, crossover strain {}\n",
      p.angular_frequency, p.reduced_frequency,
      with_error(p.plateau_storage.value, p.plateau_storage.error()),
      with_error(p.plateau_loss.value, p.plateau_loss.error()), p.amplitudes.front(),
      strain(p.softening_strain), strain(p.crossover_strain));
}

void print_rescale_report(const std::vector<RescaledCurve>& rescaled, const RescaleSettings& s,
                          const std::string& constants_source) {
  fmt::print("universal law  k = {:.4g}, k' = {:.4g} ({}); eta_s = {:.4g} Pa s\n", s.k, s.k_N1,
             constants_source, s.viscosity);
  for (const RescaledCurve& r : rescaled) {
    const HerschelBulkleyFit& hb = r.herschel_bulkley;
    fmt::print("\ncurve '{}'\n", r.label);
    // The weights are 1/τ²: χ²/(number of points) is the mean squared relative residual.
    const double points = hb.goodness.dof + 3.0;
    fmt::print("  Herschel-Bulkley  tau_y = {} Pa, K = {} Pa s^n, n = {}, rms {:.1f} %{}\n",
               with_error(hb.parameters.yield, std::sqrt(hb.covariance(0, 0))),
               with_error(hb.parameters.consistency, std::sqrt(hb.covariance(1, 1))),
               with_error(hb.parameters.exponent, std::sqrt(hb.covariance(2, 2))),
               100.0 * std::sqrt(hb.goodness.chi2 / points),
               hb.converged ? "" : "  (fit failed: " + hb.status + ")");
    fmt::print("  universal law     tau_y = {} Pa ({}), E* = {} Pa ({}), gamma_y = {}\n",
               with_error(r.yield_stress.value, r.yield_stress.error),
               r.yield_stress_fitted ? "fitted" : "given",
               with_error(r.modulus.value, r.modulus.error),
               r.modulus_shared   ? "fitted, shared by all curves"
               : r.modulus_fitted ? "fitted"
                                  : "given",
               with_error(r.yield_strain.value, r.yield_strain.error));
    fmt::print("                    rms relative residual {:.1f} %\n", 100.0 * r.rms_residual);
    if (r.rms_residual > kPoorCollapse) {
      fmt::print(
          "WARNING  the universal law misses this curve by {:.0f} % rms: look for wall slip or "
          "unsteady data at low rates (--min-rate), or a wrong yield strain\n",
          100.0 * r.rms_residual);
    }
    if (r.N1_yield) {
      fmt::print("  N1 law            N1_y = {} Pa, rms residual {:.1f} % of tau_y\n",
                 with_error(r.N1_yield->value, r.N1_yield->error), 100.0 * *r.N1_rms_residual);
    }
  }
}

}  // namespace softglass::bridge
