#include "bridge/sweep/bootstrap.h"

#include <cmath>
#include <exception>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

std::vector<double> flatten(const SweepFit& fit) {
  std::vector<double> values;
  visit_scalars(fit, [&](const std::string&, double v) { values.push_back(v); });
  return values;
}

// Sample standard deviation and correlation over the finite values.
struct Moments {
  double sd = kNaN;
  std::size_t finite = 0;
};
Moments moments(const std::vector<double>& v) {
  double sum = 0.0, sum2 = 0.0;
  Moments m;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    ++m.finite;
    sum += x;
  }
  if (m.finite < 2) return m;
  const double mean = sum / static_cast<double>(m.finite);
  for (double x : v)
    if (std::isfinite(x)) sum2 += (x - mean) * (x - mean);
  m.sd = std::sqrt(sum2 / static_cast<double>(m.finite - 1));
  return m;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double n = 0, sa = 0, sb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(a[i]) || !std::isfinite(b[i])) continue;
    ++n;
    sa += a[i];
    sb += b[i];
  }
  if (n < 3) return kNaN;
  const double ma = sa / n, mb = sb / n;
  double saa = 0, sbb = 0, sab = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(a[i]) || !std::isfinite(b[i])) continue;
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
    sab += (a[i] - ma) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : kNaN;
}

}  // namespace

BootstrapResult bootstrap(const SweepFit& estimate, const Resampler& resampler,
                          const BootstrapOptions& options,
                          const std::function<void(std::size_t)>& progress) {
  require(options.replicates >= 2, "the bootstrap needs at least 2 replicates");
  const auto replicates = static_cast<long>(options.replicates);
  std::vector<SweepFit> fits(options.replicates);
  std::size_t done = 0;

#pragma omp parallel for schedule(dynamic)
  for (long b = 0; b < replicates; ++b) {
    std::seed_seq seq{options.seed, static_cast<std::uint64_t>(b)};
    std::mt19937_64 rng(seq);
    // Failed fits already give NaN; anything thrown is a failed replicate too.
    try {
      fits[b] = fit_sweep(resampler.draw(rng)).fit;
    } catch (const std::exception&) {
      fits[b] = estimate;
      visit_scalars(fits[b], [](const std::string&, double& v) { v = kNaN; });
    }
#pragma omp critical(bootstrap_progress)
    if (progress) progress(++done);
  }

  // Standard deviations, number by number, in the flat layout.
  const std::size_t count = flatten(estimate).size();
  std::vector<std::vector<double>> columns(count, std::vector<double>(options.replicates));
  for (std::size_t b = 0; b < options.replicates; ++b) {
    const std::vector<double> v = flatten(fits[b]);
    for (std::size_t s = 0; s < count; ++s) columns[s][b] = v[s];
  }
  BootstrapResult result;
  result.replicates = options.replicates;
  result.error = estimate;
  std::size_t s = 0;
  visit_scalars(result.error, [&](const std::string& name, double& v) {
    const Moments m = moments(columns[s++]);
    v = m.sd;
    if (m.finite < options.replicates) {
      result.failures.emplace_back(
          name, 1.0 - static_cast<double>(m.finite) / static_cast<double>(options.replicates));
    }
  });

  result.log_consistency_exponent_correlation.resize(estimate.groups.size());
  for (std::size_t j = 0; j < estimate.groups.size(); ++j) {
    for (Quantity q : kAllQuantities) {
      if (!estimate.groups[j].hb[index(q)]) continue;
      std::vector<double> log_k, m;
      for (const SweepFit& f : fits) {
        const HbParameters& hb = *f.groups[j].hb[index(q)];
        log_k.push_back(std::log(std::abs(hb.consistency)));
        m.push_back(hb.exponent);
      }
      result.log_consistency_exponent_correlation[j][index(q)] = correlation(log_k, m);
    }
  }
  return result;
}

}  // namespace softglass::bridge
