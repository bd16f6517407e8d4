#include "micro/results/packing_average.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/errors.h"

namespace softglass::micro {

namespace {

struct MeanAndError {
  double mean, error;  // error: sd/√K, 0 for K = 1
};

MeanAndError mean_of(const std::vector<double>& values) {
  const double k = static_cast<double>(values.size());
  double mean = 0.0;
  for (double v : values) mean += v / k;
  if (values.size() < 2) return {mean, 0.0};
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / (k - 1.0) / k)};
}

}  // namespace

bool same_state(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

AveragedObservable average(const std::string& name, const std::vector<double>& means,
                           const std::vector<double>& errors) {
  double within2 = 0.0;
  for (double e : errors) within2 += e * e;
  const MeanAndError m = mean_of(means);
  return {name, m.mean, std::sqrt(within2) / static_cast<double>(means.size()), m.error};
}

void require_distinct_packings(const std::vector<std::filesystem::path>& files,
                               const std::vector<std::uint64_t>& fingerprints) {
  for (std::size_t i = 0; i < files.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (fingerprints[i] == fingerprints[j]) {
        throw InputError(fmt::format(
            "'{}' and '{}' start from the same packing (one run given twice, or a copy of it): "
            "averaging them would count one packing twice; average runs of different packings",
            files[j].string(), files[i].string()));
      }
}

const AveragedObservable& PackingAverage::operator[](const std::string& name) const {
  for (const auto& o : observables)
    if (o.name == name) return o;
  throw std::invalid_argument("no observable " + name);
}

PackingAverage average_over_packings(const std::vector<StoredRunSummary>& runs) {
  if (runs.empty()) throw InputError("no run files to average");
  const StoredRunSummary& first = runs.front();
  for (const auto& r : runs) {
    if (!same_state(r.gamma_tilde, first.gamma_tilde) ||
        !same_state(r.volume_fraction, first.volume_fraction) || r.particles != first.particles) {
      throw InputError(fmt::format(
          "'{}' (gamma~ = {:.4g}, phi = {:.4f}, N = {}) is not at the state point of '{}' (gamma~ "
          "= "
          "{:.4g}, phi = {:.4f}, N = {}); average runs of one state point only",
          r.file.string(), r.gamma_tilde, r.volume_fraction, r.particles, first.file.string(),
          first.gamma_tilde, first.volume_fraction, first.particles));
    }
  }

  std::vector<std::filesystem::path> files;
  std::vector<std::uint64_t> fingerprints;
  for (const auto& r : runs) {
    files.push_back(r.file);
    fingerprints.push_back(r.packing_fingerprint);
  }
  require_distinct_packings(files, fingerprints);

  PackingAverage a;
  a.runs = runs.size();
  a.particles = first.particles;
  a.gamma_tilde = first.gamma_tilde;
  a.volume_fraction = first.volume_fraction;
  std::vector<double> moduli;
  for (const auto& r : runs) {
    a.converged_runs += r.converged;
    a.averaged_strain += r.averaged_strain;
    a.coordination += r.coordination / static_cast<double>(runs.size());
    moduli.push_back(r.shear_modulus);
  }
  const MeanAndError g = mean_of(moduli);
  a.shear_modulus = g.mean;
  a.shear_modulus_error = g.error;

  for (std::size_t q = 0; q < first.observables.size(); ++q) {
    std::vector<double> means, errors;
    for (const auto& r : runs) {
      means.push_back(r.observables[q].estimate.mean);
      errors.push_back(r.observables[q].estimate.standard_error);
    }
    a.observables.push_back(average(first.observables[q].name, means, errors));
  }

  const bool structure =
      std::all_of(runs.begin(), runs.end(), [](const auto& r) { return r.f_m.has_value(); });
  if (structure) {
    std::vector<double> r_m, r_m_error, f_m, f_m_error;
    for (const auto& r : runs) {
      r_m.push_back(r.r_m->value);
      r_m_error.push_back(r.r_m->error);
      f_m.push_back(r.f_m->value);
      f_m_error.push_back(r.f_m->error);
    }
    a.r_m = average("r_m", r_m, r_m_error);
    a.f_m = average("f_m", f_m, f_m_error);
  }
  return a;
}

}  // namespace softglass::micro
