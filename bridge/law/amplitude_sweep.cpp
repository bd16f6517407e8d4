#include "bridge/law/amplitude_sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

bool same(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

double relative(const Estimate& e) {
  return e.value != 0.0 ? e.error / std::abs(e.value) : 0.0;
}

}  // namespace

Estimate first_crossing(const std::vector<double>& amplitudes, const std::vector<double>& f,
                        const std::vector<double>& f_error, const std::vector<double>& common) {
  for (std::size_t k = 1; k < f.size(); ++k) {
    if (!(f[k] <= 0.0 && f[k - 1] > 0.0)) continue;
    const double a = std::log(amplitudes[k - 1]), b = std::log(amplitudes[k]);
    if (!(b > a)) continue;  // a strain measured twice brackets nothing
    const double slope = (f[k] - f[k - 1]) / (b - a);
    const double at = a - f[k - 1] / slope;
    const double w = (at - a) / (b - a);
    const double shared = common.empty() ? 0.0 : (1 - w) * common[k - 1] + w * common[k];
    const double error =
        std::hypot(std::hypot((1 - w) * f_error[k - 1], w * f_error[k]), shared) / std::abs(slope);
    return {std::exp(at), std::exp(at) * error};
  }
  return {0.0, 0.0};
}

SweepStrains sweep_strains(const std::vector<double>& amplitudes,
                           const std::vector<Estimate>& storage,
                           const std::vector<Estimate>& loss) {
  // ln(G′/(0.9 G′_plateau)) and ln(G′/G″), both decreasing through 0 where the
  // strains are. Each amplitude's own errors are independent; the plateau's
  // shifts every softening value but its own (ln(1/0.9) exactly) together.
  const Estimate& plateau = storage.front();
  std::vector<double> softening, softening_error, plateau_shift, crossing, crossing_error;
  for (std::size_t k = 0; k < storage.size(); ++k) {
    const double g = std::max(storage[k].value, 1e-300);
    softening.push_back(std::log(g / (kSoftening * plateau.value)));
    softening_error.push_back(k ? relative(storage[k]) : 0.0);
    plateau_shift.push_back(k ? relative(plateau) : 0.0);
    crossing.push_back(loss[k].value > 0.0 ? std::log(g / loss[k].value) : 1.0);
    crossing_error.push_back(std::hypot(relative(storage[k]), relative(loss[k])));
  }
  return {first_crossing(amplitudes, softening, softening_error, plateau_shift),
          first_crossing(amplitudes, crossing, crossing_error)};
}

AmplitudeSweepLaw make_amplitude_sweep_law(const OscillationTable& table,
                                           std::optional<double> frequency) {
  std::set<double> frequencies;
  for (const OscillationPoint& p : table.points) frequencies.insert(p.frequency);
  AmplitudeSweepLaw law;
  if (frequency) {
    const auto it = std::find_if(frequencies.begin(), frequencies.end(),
                                 [&](double f) { return same(f, *frequency); });
    if (it == frequencies.end())
      throw InputError(
          fmt::format("{}: no amplitude sweep at omega~ = {}", table.source, *frequency));
    law.frequency = *it;
  } else if (frequencies.size() == 1) {
    law.frequency = *frequencies.begin();
  } else {
    std::string list;
    for (double f : frequencies) list += (list.empty() ? "" : ", ") + fmt::format("{}", f);
    throw InputError(fmt::format(
        "{}: the table holds amplitude sweeps at several frequencies ({}); choose one with "
        "--oscillation-frequency",
        table.source, list));
  }
  std::map<double, std::map<double, const OscillationPoint*>> by_phi;  // φ → γ0 → point
  for (const OscillationPoint& p : table.points)
    if (same(p.frequency, law.frequency)) by_phi[p.phi][p.amplitude] = &p;
  for (const auto& [phi, sweep] : by_phi) {
    std::vector<double> amplitudes;
    for (const auto& [gamma0, point] : sweep) amplitudes.push_back(gamma0);
    if (law.amplitudes.empty()) law.amplitudes = amplitudes;
    if (amplitudes.size() != law.amplitudes.size() ||
        !std::equal(amplitudes.begin(), amplitudes.end(), law.amplitudes.begin(), same))
      throw InputError(fmt::format(
          "{}: phi = {} has other amplitudes than phi = {}; an amplitude-sweep law needs the same "
          "amplitudes at every volume fraction",
          table.source, phi, by_phi.begin()->first));
    law.phi.push_back(phi);
    std::vector<Estimate> storage, loss;
    std::size_t packings = std::numeric_limits<std::size_t>::max();
    for (const auto& [gamma0, point] : sweep) {
      storage.push_back(point->storage);
      loss.push_back(point->loss);
      packings = std::min(packings, point->packings);
    }
    law.packings.push_back(static_cast<double>(packings));
    if (storage.front().value <= 0.0)
      throw InputError(fmt::format("{}: phi = {}: G' = {} at the smallest amplitude; allowed: > 0",
                                   table.source, phi, storage.front().value));
    const SweepStrains strains = sweep_strains(law.amplitudes, storage, loss);
    law.storage.push_back(storage);
    law.loss.push_back(loss);
    law.plateau_storage.push_back(storage.front());
    law.plateau_loss.push_back(loss.front());
    law.softening_strain.push_back(strains.softening);
    law.crossover_strain.push_back(strains.crossover);
    if (packings < 2) mark_errors_unknown(law, law.phi.size() - 1);
  }
  if (law.amplitudes.size() < 3)
    throw InputError(
        fmt::format("{}: an amplitude sweep needs at least three amplitudes ({} given)",
                    table.source, law.amplitudes.size()));
  return law;
}

void mark_errors_unknown(AmplitudeSweepLaw& law, std::size_t i) {
  for (auto* rows : {&law.storage, &law.loss})
    for (Estimate& e : (*rows)[i]) e.error = NAN;
  for (auto* per_phi :
       {&law.plateau_storage, &law.plateau_loss, &law.softening_strain, &law.crossover_strain})
    (*per_phi)[i].error = NAN;
}

void validate(const AmplitudeSweepLaw& law, const std::string& source) {
  const auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("{}: subsection law/amplitude sweep: {}", source, what));
  };
  if (!(law.frequency > 0.0 && std::isfinite(law.frequency))) fail("'frequency' must be > 0");
  if (law.phi.empty()) fail("'volume fractions' is empty");
  if (law.amplitudes.size() < 3) fail("'amplitudes' needs at least three values");
  for (std::size_t k = 0; k < law.amplitudes.size(); ++k)
    if (!(law.amplitudes[k] > 0.0) || (k && !(law.amplitudes[k] > law.amplitudes[k - 1])))
      fail("'amplitudes' must be positive and increasing");
  for (std::size_t i = 0; i < law.phi.size(); ++i)
    if (!(law.phi[i] > 0.0 && law.phi[i] < 1.0) || (i && !(law.phi[i] > law.phi[i - 1])))
      fail("'volume fractions' must lie in (0, 1) and increase");
  for (const auto* moduli : {&law.storage, &law.loss})
    if (moduli->size() != law.phi.size())
      fail("'storage' and 'loss' need a row per volume fraction");
  for (const auto* per_phi :
       {&law.plateau_storage, &law.plateau_loss, &law.softening_strain, &law.crossover_strain})
    if (per_phi->size() != law.phi.size())
      fail("the plateaus and strains need one value per volume fraction");
  if (!law.packings.empty() && law.packings.size() != law.phi.size())
    fail("'packings' needs one value per volume fraction");
  for (std::size_t i = 0; i < law.phi.size(); ++i) {
    // An error is >= 0, or n/a (NaN) where the rows are one packing's.
    const auto error_ok = [&](double e) { return e >= 0.0 || (std::isnan(e) && law.one_packing(i)); };
    for (const auto* moduli : {&law.storage, &law.loss}) {
      if ((*moduli)[i].size() != law.amplitudes.size())
        fail("'storage' and 'loss' need a value per volume fraction and amplitude");
      for (const Estimate& e : (*moduli)[i])
        if (!std::isfinite(e.value) || !error_ok(e.error))
          fail("moduli must be finite, errors >= 0");
    }
    if (!(law.plateau_storage[i].value > 0.0)) fail("'plateau storage' must be > 0");
    if (!std::isfinite(law.plateau_loss[i].value) || !error_ok(law.plateau_loss[i].error))
      fail("'plateau loss' must be finite, its error >= 0");
    for (const auto* strains : {&law.softening_strain, &law.crossover_strain})
      if (!((*strains)[i].value >= 0.0) || !error_ok((*strains)[i].error))
        fail("strains must be >= 0 (0: not reached) with errors >= 0");
  }
}

}  // namespace softglass::bridge
