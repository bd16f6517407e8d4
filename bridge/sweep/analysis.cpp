#include "bridge/sweep/analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "common/warning_collector.h"

namespace softglass::bridge {

namespace {

constexpr double kMissesData = 1e-3;  // p-value below which a law misses its data
constexpr double kPoorRelativeError = 0.25;
constexpr double kPoorExponentError = 0.1;
constexpr double kTolerableFailures = 0.01;

const char* universal_name(Quantity q) {
  return q == Quantity::sigma ? "k (sigma)" : q == Quantity::N1 ? "k' (N1)" : "k'' (N2)";
}

std::string goodness_text(const GoodnessOfFit& g) {
  return fmt::format("chi2/dof = {:.3g} with {} degrees of freedom, p = {:.2g}", g.reduced_chi2(),
                     g.dof, g.p_value);
}

// Refusals and failures of the original fit: only the stress law is essential.
void require_stress_law(const Sweep& sweep, const SweepFitOutcome& outcome) {
  for (std::size_t j = 0; j < sweep.groups.size(); ++j) {
    const PhiGroup& g = sweep.groups[j];
    const HerschelBulkleyFit& hb = *outcome.diagnostics.hb[j][index(Quantity::sigma)];
    if (!hb.converged) {
      throw NumericalError(
          fmt::format("phi = {}: the Herschel-Bulkley fit of sigma failed: {}", g.phi, hb.status));
    }
    const PlateauCheck plateau = check_plateau(*g.curves[index(Quantity::sigma)], hb);
    if (!plateau.ok) throw InputError(fmt::format("phi = {}, sigma: {}", g.phi, plateau.reason));
  }
  const UniversalFit& universal = *outcome.diagnostics.universal[index(Quantity::sigma)];
  if (!universal.converged) {
    throw NumericalError("the universal stress fit failed: " + universal.status);
  }
}

// One line per kind of warning, its places (volume fraction and quantity) listed.
void warn_about_fits(const SweepAnalysis& a, WarningCollector& warnings) {
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const PhiGroup& g = a.sweep.groups[j];
    const GroupFit& error = a.uncertainty.error.groups[j];
    const GroupFit& value = a.estimate.fit.groups[j];
    for (Quantity q : kAllQuantities) {
      if (!g.curves[index(q)]) continue;
      const std::string where = fmt::format("phi = {}, {}", g.phi, column_name(q));
      const HerschelBulkleyFit& hb = *a.estimate.diagnostics.hb[j][index(q)];
      if (!hb.converged) {
        warnings.add("the Herschel-Bulkley fit failed: " + hb.status, where);
        continue;
      }
      if (hb.goodness.p_value < kMissesData) {
        warnings.add(fmt::format("the Herschel-Bulkley law misses the data (p < {:g})", kMissesData),
                     where + " (" + goodness_text(hb.goodness) + ")");
      }
      if (q != Quantity::sigma) {
        const PlateauCheck plateau = check_plateau(*g.curves[index(q)], hb);
        if (!plateau.ok) warnings.add(plateau.reason, where);
      }
      const HbParameters& v = *value.hb[index(q)];
      const HbParameters& e = *error.hb[index(q)];
      // Not the consistency: it is the value at γ̃ = 1, far outside the data, and
      // its error mostly mirrors the exponent's (their correlation is ~0.99).
      if (e.yield > kPoorRelativeError * std::abs(v.yield) || e.exponent > kPoorExponentError) {
        warnings.add(
            fmt::format("the Herschel-Bulkley law is poorly determined (a yield stress error over "
                        "{:.0f} % or an exponent error over {:g}; the values in the _phi.csv table)",
                        100.0 * kPoorRelativeError, kPoorExponentError),
            where);
      }
    }
  }
}

// Cochran's test: Q = Σ w_j (k_j − k̄)², w_j = 1/SE_j², k̄ = Σ w_j k_j / Σ w_j.
GoodnessOfFit homogeneity(const SweepAnalysis& a, Quantity q) {
  double sw = 0.0, swk = 0.0;
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const double w = 1.0 / std::pow(*a.uncertainty.error.groups[j].own_k[index(q)], 2);
    sw += w;
    swk += w * *a.estimate.fit.groups[j].own_k[index(q)];
  }
  double q_statistic = 0.0;
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    q_statistic += std::pow((*a.estimate.fit.groups[j].own_k[index(q)] - swk / sw) /
                                *a.uncertainty.error.groups[j].own_k[index(q)],
                            2);
  }
  return goodness_of_fit(q_statistic, static_cast<int>(a.sweep.groups.size()) - 1);
}

void warn_about_collapse(const SweepAnalysis& a, std::vector<std::string>& warnings) {
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
    const auto& universal = a.estimate.diagnostics.universal[index(q)];
    if (!universal) continue;
    if (!universal->converged) {
      warnings.push_back(
          fmt::format("{}: the universal fit failed: {}", universal_name(q), universal->status));
      continue;
    }
    const double k = *a.estimate.fit.k[index(q)], error = *a.uncertainty.error.k[index(q)];
    if (error > kPoorRelativeError * std::abs(k)) {
      warnings.push_back(
          fmt::format("{}: poorly determined: {:.3g} ± {:.2g}", universal_name(q), k, error));
    }
    const auto& collapse = a.collapse[index(q)];
    if (collapse && collapse->p_value < kMissesData) {
      std::string own;
      for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
        own += fmt::format("{}{:.3g} ± {:.2g} (phi {})", own.empty() ? "" : ", ",
                           *a.estimate.fit.groups[j].own_k[index(q)],
                           *a.uncertainty.error.groups[j].own_k[index(q)], a.sweep.groups[j].phi);
      }
      warnings.push_back(fmt::format(
          "{}: the volume fractions do not collapse within their errors (Cochran's Q/dof = "
          "{:.3g}, p = {:.2g}); each phi's own value: {}",
          universal_name(q), collapse->reduced_chi2(), collapse->p_value, own));
    }
  }
}

}  // namespace

SweepAnalysis analyse_sweep(const Sweep& sweep, const Resampler& resampler,
                            const BootstrapOptions& options,
                            const std::function<void(std::size_t)>& progress) {
  SweepAnalysis a;
  a.sweep = sweep;
  a.estimate = fit_sweep(sweep);
  require_stress_law(sweep, a.estimate);
  a.uncertainty = bootstrap(a.estimate.fit, resampler, options, progress);
  a.method = fmt::format("{}; {} replicates, seed {}", resampler.description(), options.replicates,
                         options.seed);
  if (a.sweep.groups.size() >= 2) {
    for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2})
      if (a.sweep.present[index(q)]) a.collapse[index(q)] = homogeneity(a, q);
  }
  if (!sweep.unconverged.empty()) {
    // The first few by name; a sweep that missed its stopping rule everywhere
    // would otherwise bury the other warnings.
    constexpr std::size_t kNamed = 5;
    std::string points;
    for (std::size_t i = 0; i < std::min(kNamed, sweep.unconverged.size()); ++i)
      points += (points.empty() ? "" : "; ") + sweep.unconverged[i];
    if (sweep.unconverged.size() > kNamed)
      points += fmt::format("; and {} more", sweep.unconverged.size() - kNamed);
    a.warnings.push_back(fmt::format(
        "{} state point(s) average runs that did not meet their stopping rule (not stationary: "
        "their values and errors are less reliable): {}",
        sweep.unconverged.size(), points));
  }
  WarningCollector fits;
  warn_about_fits(a, fits);
  for (const std::string& line : fits.lines()) a.warnings.push_back(line);
  warn_about_collapse(a, a.warnings);
  WarningCollector failures;
  for (const auto& [name, fraction] : a.uncertainty.failures) {
    if (fraction > kTolerableFailures) {
      failures.add(
          fmt::format("more than {:g} % of the bootstrap replicates failed to fit; the error is "
                      "unreliable",
                      100.0 * kTolerableFailures),
          fmt::format("{} ({:.1f} %)", name, 100.0 * fraction));
    }
  }
  for (const std::string& line : failures.lines()) a.warnings.push_back(line);
  return a;
}

}  // namespace softglass::bridge
