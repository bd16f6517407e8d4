#include "bridge/law/law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

bool finite(const Estimate& e) {
  return std::isfinite(e.value) && std::isfinite(e.error);
}
bool finite(const std::vector<Estimate>& list) {
  return std::all_of(list.begin(), list.end(), [](const Estimate& e) { return finite(e); });
}

// A fit of N1, N2 or f_m that failed (on the sweep or in too many bootstrap
// replicates) leaves NaN in its numbers, and `fit` has warned about it. Such a
// part is left out of the law, with a note, so that every law `fit` writes can
// be read back: the shear law is required (`fit` refuses a sweep without it).
void leave_out_failures(Law& law) {
  const auto note = [&](const std::string& what) {
    law.provenance.push_back(what +
                             ": left out of the law, its fit or its errors failed (see "
                             "the warnings)");
  };
  for (Quantity q : {Quantity::N1, Quantity::N2, Quantity::force}) {
    auto& hb = law.hb[index(q)];
    if (!hb) continue;
    const bool correlated = std::all_of(hb->correlation.begin(), hb->correlation.end(),
                                        [](double r) { return std::abs(r) <= 1.0; });
    if (!finite(hb->yield) || !finite(hb->consistency) || !finite(hb->exponent) || !correlated) {
      hb.reset();
      note(std::string(column_name(q)) + " Herschel-Bulkley law");
    }
  }
  for (Quantity q : {Quantity::N1, Quantity::N2}) {
    if (law.k[index(q)] && !finite(*law.k[index(q)])) {
      law.k[index(q)].reset();
      note(std::string("universal constant of ") + column_name(q));
    }
  }
  if (law.force && (!finite(law.force->yield) || !finite(law.force->slope))) {
    law.force.reset();
    note("force law f_m = f_y + k_f gamma~^(1/2)");
  }
}

}  // namespace

Law make_law(const SweepAnalysis& a, std::vector<std::string> provenance) {
  Law law;
  law.provenance = std::move(provenance);
  law.gamma_tilde_min = INFINITY;
  law.gamma_tilde_max = 0.0;
  const SweepFit& value = a.estimate.fit;
  const SweepFit& error = a.uncertainty.error;
  for (Quantity q : kAllQuantities)
    if (a.sweep.present[index(q)]) law.hb[index(q)].emplace();
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const PhiGroup& g = a.sweep.groups[j];
    const GroupFit &v = value.groups[j], &e = error.groups[j];
    const std::vector<double>& rates = g.curves[index(Quantity::sigma)]->x;
    law.gamma_tilde_min = std::min(law.gamma_tilde_min, rates.front());
    law.gamma_tilde_max = std::max(law.gamma_tilde_max, rates.back());
    law.phi.push_back(g.phi);
    const double packings = static_cast<double>(*std::min_element(g.packings.begin(), g.packings.end()));
    law.packings.push_back(packings);
    law.modulus.push_back({v.modulus, packings < 2 ? NAN : e.modulus});
    law.yield_strain.push_back({v.yield_strain, e.yield_strain});
    for (Quantity q : kAllQuantities) {
      if (!law.hb[index(q)]) continue;
      HbLaw& hb = *law.hb[index(q)];
      const HbParameters &pv = *v.hb[index(q)], &pe = *e.hb[index(q)];
      hb.yield.push_back({pv.yield, pe.yield});
      hb.consistency.push_back({pv.consistency, pe.consistency});
      hb.exponent.push_back({pv.exponent, pe.exponent});
      hb.correlation.push_back(*a.uncertainty.log_consistency_exponent_correlation[j][index(q)]);
    }
  }
  if (a.sweep.present[index(Quantity::force)]) {
    ForceLaw& force = law.force.emplace();
    for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
      const GroupFit &v = value.groups[j], &e = error.groups[j];
      force.yield.push_back({*v.force_yield, *e.force_yield});
      force.slope.push_back({*v.force_slope, *e.force_slope});
    }
  }
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2})
    if (value.k[index(q)]) law.k[index(q)] = Estimate{*value.k[index(q)], *error.k[index(q)]};
  law.mean_exponent = {value.mean_exponent, error.mean_exponent};
  leave_out_failures(law);
  return law;
}

namespace {

void require_size(std::size_t size, std::size_t expected, const std::string& source,
                  const std::string& entry) {
  if (size != expected) {
    throw InputError(fmt::format("{}: '{}' has {} value(s), expected one per volume fraction ({})",
                                 source, entry, size, expected));
  }
}

void require_finite(const Estimate& e, const std::string& source, const std::string& entry) {
  if (!std::isfinite(e.value) || !std::isfinite(e.error) || e.error < 0) {
    throw InputError(
        fmt::format("{}: '{}' = {} ± {} is not a finite value with a non-negative "
                    "error",
                    source, entry, e.value, e.error));
  }
}

}  // namespace

std::filesystem::path beside(const std::filesystem::path& main, const std::string& suffix) {
  return main.parent_path() / (main.stem().string() + suffix);
}

void validate(const Law& law, const std::string& source) {
  const std::size_t n = law.phi.size();
  if (n == 0) throw InputError(source + ": the law has no volume fractions");
  for (std::size_t j = 0; j < n; ++j) {
    if (!(law.phi[j] > 0 && law.phi[j] < 1) || (j > 0 && !(law.phi[j] > law.phi[j - 1]))) {
      throw InputError(source + ": 'volume fractions' must increase strictly within (0, 1)");
    }
  }
  if (!(law.gamma_tilde_min > 0 && law.gamma_tilde_max >= law.gamma_tilde_min)) {
    throw InputError(source + ": 'gamma tilde range' must be two increasing positive rates");
  }
  require_size(law.modulus.size(), n, source, "shear modulus");
  require_size(law.yield_strain.size(), n, source, "yield strain");
  if (!law.hb[index(Quantity::sigma)]) throw InputError(source + ": subsection 'sigma' is missing");
  for (std::size_t j = 0; j < n; ++j) {
    const bool one_packing = !law.packings.empty() && law.packings[j] < 2;
    require_finite({law.modulus[j].value, one_packing ? 0.0 : law.modulus[j].error}, source,
                   "shear modulus");
    require_finite(law.yield_strain[j], source, "yield strain");
  }
  for (Quantity q : kAllQuantities) {
    if (!law.hb[index(q)]) continue;
    const HbLaw& hb = *law.hb[index(q)];
    const std::string name = law_subsection(q);
    require_size(hb.yield.size(), n, source, name + "/yield");
    require_size(hb.consistency.size(), n, source, name + "/consistency");
    require_size(hb.exponent.size(), n, source, name + "/exponent");
    require_size(hb.correlation.size(), n, source, name + "/correlation");
    for (std::size_t j = 0; j < n; ++j) {
      require_finite(hb.yield[j], source, name + "/yield");
      require_finite(hb.consistency[j], source, name + "/consistency");
      require_finite(hb.exponent[j], source, name + "/exponent");
      if (!(hb.exponent[j].value > 0 && hb.exponent[j].value <= 2)) {
        throw InputError(
            fmt::format("{}: {}/exponent = {} outside (0, 2]", source, name, hb.exponent[j].value));
      }
      if (!(std::abs(hb.correlation[j]) <= 1)) {
        throw InputError(fmt::format("{}: {}/correlation = {} outside [-1, 1]", source, name,
                                     hb.correlation[j]));
      }
    }
  }
  if (law.force) {
    require_size(law.force->yield.size(), n, source, "f_m/f_y");
    require_size(law.force->slope.size(), n, source, "f_m/k_f");
    for (std::size_t j = 0; j < n; ++j) {
      require_finite(law.force->yield[j], source, "f_m/f_y");
      require_finite(law.force->slope[j], source, "f_m/k_f");
    }
  }
  const std::pair<Quantity, const char*> constants[] = {{Quantity::sigma, "universal/k"},
                                                        {Quantity::N1, "universal/k N1"},
                                                        {Quantity::N2, "universal/k N2"}};
  for (const auto& [q, entry] : constants)
    if (law.k[index(q)]) require_finite(*law.k[index(q)], source, entry);
  require_finite(law.mean_exponent, source, "universal/mean exponent");
  const HbLaw& sigma = *law.hb[index(Quantity::sigma)];
  for (std::size_t j = 0; j < n; ++j) {
    if (!(sigma.yield[j].value > 0 && sigma.consistency[j].value > 0)) {
      throw InputError(source + ": sigma/yield and sigma/consistency must be positive");
    }
  }
  if (law.amplitude_sweep) validate(*law.amplitude_sweep, source);
}

}  // namespace softglass::bridge
