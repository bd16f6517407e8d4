#include "micro/results/oscillation_table.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"
#include "common/oscillation_columns.h"

namespace softglass::micro {

namespace {

namespace columns = softglass::oscillation_table;

void add_column(UnitTable& t, const std::string& name) {
  t.columns.push_back({name, columns::unit_of(name)});
}

void add_state_columns(UnitTable& t, const char* last) {
  for (const char* name : {columns::phi, columns::frequency, columns::amplitude, last})
    add_column(t, name);
}

void add_response_columns(UnitTable& t) {
  for (const char* name : columns::responses) {
    add_column(t, name);
    add_column(t, columns::error_of(name));
  }
}

}  // namespace

OscillationAverage average_oscillations(const std::vector<StoredOscillationSummary>& runs) {
  if (runs.empty()) throw InputError("no oscillatory runs to average");
  const StoredOscillationSummary& first = runs.front();
  std::vector<std::filesystem::path> files;
  std::vector<std::uint64_t> fingerprints;
  for (const auto& r : runs) {
    if (!same_state(r.volume_fraction, first.volume_fraction) ||
        !same_state(r.amplitude, first.amplitude) || !same_state(r.frequency, first.frequency) ||
        r.particles != first.particles)
      throw InputError(fmt::format(
          "'{}' (phi = {:.4f}, gamma0 = {:.4g}, omega~ = {:.4g}, N = {}) is not at the state point "
          "of '{}'; average runs of one state point only",
          r.file.string(), r.volume_fraction, r.amplitude, r.frequency, r.particles,
          first.file.string()));
    files.push_back(r.file);
    fingerprints.push_back(r.packing_fingerprint);
  }
  require_distinct_packings(files, fingerprints);

  OscillationAverage a;
  a.runs = runs.size();
  a.particles = first.particles;
  a.volume_fraction = first.volume_fraction;
  a.amplitude = first.amplitude;
  a.frequency = first.frequency;
  std::vector<double> moduli, xy_moduli, no_errors(runs.size(), 0.0);
  for (const auto& r : runs) {
    a.converged_runs += r.converged;
    a.periodic_cycles += r.periodic_cycles;
    moduli.push_back(r.shear_modulus);
    xy_moduli.push_back(r.flow_gradient_modulus);
  }
  a.shear_modulus = average(columns::shear_modulus, moduli, no_errors);
  a.flow_gradient_modulus = average(columns::flow_gradient_modulus, xy_moduli, no_errors);
  for (std::size_t q = 0; q < first.observables.size(); ++q) {
    std::vector<double> means, errors;
    for (const auto& r : runs) {
      means.push_back(r.observables[q].estimate.mean);
      errors.push_back(r.observables[q].estimate.standard_error);
    }
    a.observables.push_back(average(first.observables[q].name, means, errors));
  }
  return a;
}

UnitTable oscillation_table(const std::vector<OscillationAverage>& points) {
  UnitTable t;
  add_state_columns(t, columns::packings);
  add_response_columns(t);
  for (const char* modulus : {columns::shear_modulus, columns::flow_gradient_modulus}) {
    add_column(t, modulus);
    add_column(t, columns::error_of(modulus));
  }
  add_column(t, columns::cycles);
  add_column(t, columns::converged);
  for (const auto& p : points) {
    std::vector<double> row = {p.volume_fraction, p.frequency, p.amplitude,
                               static_cast<double>(p.runs)};
    for (const auto& o : p.observables) {
      row.push_back(o.mean);
      row.push_back(o.standard_error());
    }
    row.insert(row.end(),
               {p.shear_modulus.mean, p.shear_modulus.standard_error(),
                p.flow_gradient_modulus.mean, p.flow_gradient_modulus.standard_error(),
                static_cast<double>(p.periodic_cycles), static_cast<double>(p.converged_runs)});
    t.rows.push_back(std::move(row));
  }
  return t;
}

UnitTable oscillation_packing_table(const std::vector<StoredOscillationSummary>& runs,
                                    const std::vector<unsigned>& seeds) {
  UnitTable t;
  add_state_columns(t, columns::seed);
  add_response_columns(t);
  add_column(t, columns::shear_modulus);
  add_column(t, columns::flow_gradient_modulus);
  add_column(t, columns::cycles);
  add_column(t, columns::converged);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const StoredOscillationSummary& r = runs[k];
    std::vector<double> row = {r.volume_fraction, r.frequency, r.amplitude,
                               static_cast<double>(seeds.at(k))};
    for (const auto& o : r.observables) {
      row.push_back(o.estimate.mean);
      row.push_back(o.estimate.standard_error);
    }
    row.insert(row.end(),
               {r.shear_modulus, r.flow_gradient_modulus, static_cast<double>(r.periodic_cycles),
                r.converged ? 1.0 : 0.0});
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace softglass::micro
