#include "synthetic_sweep.h"

#include <fmt/format.h>

#include <cmath>
#include <random>

namespace softglass::bridge::testing {

SyntheticTruth::SyntheticTruth() {
  for (int i = 0; i <= 10; ++i) gamma_tilde.push_back(std::pow(10.0, -9.0 + 0.5 * i));
}

double SyntheticTruth::sigma(std::size_t j, double g) const {
  return sigma_yield(j) * (1.0 + k * std::sqrt(g) / yield_strain[j]);
}

double SyntheticTruth::normal_yield(std::size_t j, Quantity q) const {
  return (q == Quantity::N1 ? N1_ratio : N2_ratio) * sigma_yield(j);
}

double SyntheticTruth::value(std::size_t j, Quantity q, double g) const {
  switch (q) {
    case Quantity::sigma:
      return sigma(j, g);
    case Quantity::N1:
      return normal_yield(j, q) + k_N1 * sigma_yield(j) * std::sqrt(g) / yield_strain[j];
    case Quantity::N2:
      return normal_yield(j, q) - k_N2 * sigma_yield(j) * std::sqrt(g) / yield_strain[j];
    case Quantity::force:
      return modulus[j] * (force_yield + force_slope * std::sqrt(g));
  }
  return 0.0;
}

namespace {

struct MeanAndError {
  double mean = 0.0, error = 0.0;
};
MeanAndError average(const std::vector<double>& v) {
  double sum = 0.0, sum2 = 0.0;
  for (double x : v) sum += x;
  const double n = static_cast<double>(v.size()), mean = sum / n;
  for (double x : v) sum2 += (x - mean) * (x - mean);
  return {mean, std::sqrt(sum2 / (n - 1.0) / n)};
}

}  // namespace

SyntheticSweep make_synthetic_sweep(const SyntheticTruth& truth, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  SyntheticSweep out;
  out.table.source = "synthetic";
  out.table.present = {true, truth.normal, truth.normal, truth.force};
  const auto noise = [&](Quantity q) {
    return q == Quantity::sigma   ? truth.sigma_noise
           : q == Quantity::force ? truth.force_noise
                                  : truth.normal_noise;
  };
  std::size_t line = 1;
  for (std::size_t j = 0; j < truth.phi.size(); ++j) {
    std::vector<double> moduli;
    for (std::size_t s = 0; s < truth.packings; ++s)
      moduli.push_back(truth.modulus[j] * (1.0 + truth.modulus_noise * normal(rng)));
    const MeanAndError g0 = average(moduli);
    for (double g : truth.gamma_tilde) {
      StatePoint p;
      p.phi = truth.phi[j];
      p.gamma_tilde = g;
      p.packings = truth.packings;
      p.modulus = {g0.mean, g0.error};
      p.line = ++line;
      std::vector<PackingRun> runs(truth.packings);
      for (std::size_t s = 0; s < truth.packings; ++s) {
        runs[s].phi = truth.phi[j];
        runs[s].gamma_tilde = g;
        runs[s].seed = s + 1;
        runs[s].modulus = moduli[s];
      }
      for (Quantity q : kAllQuantities) {
        if (!out.table.present[index(q)]) continue;
        std::vector<double> values;
        for (PackingRun& run : runs) {
          const double v = truth.value(j, q, g) * (1.0 + noise(q) * normal(rng));
          run.values[index(q)] = v;
          values.push_back(v);
        }
        const MeanAndError m = average(values);
        p.values[index(q)] = Estimate{m.mean, m.error};
      }
      out.table.points.push_back(p);
      out.runs.insert(out.runs.end(), runs.begin(), runs.end());
    }
  }
  return out;
}

namespace {

std::string header(const SyntheticSweep& s, bool runs) {
  std::string h =
      runs ? "phi [1],gamma_tilde [1],seed [1]" : "phi [1],gamma_tilde [1],packings [1]";
  for (Quantity q : kAllQuantities) {
    if (!s.table.present[index(q)]) continue;
    h += fmt::format(",{} [{}]", column_name(q), reduced_units(q));
    if (!runs) h += fmt::format(",{}_se [{}]", column_name(q), reduced_units(q));
  }
  return h + (runs ? ",G0 [E*]\n" : ",G0 [E*],G0_se [E*]\n");
}

}  // namespace

std::string table_csv(const SyntheticSweep& s) {
  std::string text = "# synthetic sweep (tests/bridge/synthetic_sweep.cpp)\n" + header(s, false);
  for (const StatePoint& p : s.table.points) {
    text += fmt::format("{},{:.6e},{}", p.phi, p.gamma_tilde, p.packings);
    for (Quantity q : kAllQuantities)
      if (p.values[index(q)])
        text +=
            fmt::format(",{:.10e},{:.6e}", p.values[index(q)]->value, p.values[index(q)]->error);
    text += fmt::format(",{:.10e},{:.6e}\n", p.modulus.value, p.modulus.error);
  }
  return text;
}

std::string runs_csv(const SyntheticSweep& s) {
  std::string text = "# synthetic sweep, one row per run\n" + header(s, true);
  for (const PackingRun& r : s.runs) {
    text += fmt::format("{},{:.6e},{}", r.phi, r.gamma_tilde, r.seed);
    for (Quantity q : kAllQuantities)
      if (r.values[index(q)]) text += fmt::format(",{:.10e}", *r.values[index(q)]);
    text += fmt::format(",{:.10e}\n", r.modulus);
  }
  return text;
}

std::string structure_csv(const SyntheticSweep& s) {
  std::string text =
      "# synthetic structure, one row per state point\nphi [1],gamma_tilde [1],f_m [E*R^2],"
      "f_m_se [E*R^2]\n";
  for (const StatePoint& p : s.table.points) {
    const Estimate& f = *p.values[index(Quantity::force)];
    text += fmt::format("{},{:.6e},{:.10e},{:.6e}\n", p.phi, p.gamma_tilde, f.value, f.error);
  }
  return text;
}

SyntheticSweep without_structure(SyntheticSweep s) {
  s.table.present[index(Quantity::force)] = false;
  for (StatePoint& p : s.table.points) p.values[index(Quantity::force)].reset();
  for (PackingRun& r : s.runs) r.values[index(Quantity::force)].reset();
  return s;
}

SyntheticSweep with_quasi_static(SyntheticSweep sweep, SyntheticTruth truth, std::uint64_t seed) {
  truth.gamma_tilde = {0.0};
  const SyntheticSweep quasi_static = make_synthetic_sweep(truth, seed);
  std::size_t line = sweep.table.points.empty() ? 1 : sweep.table.points.back().line;
  for (StatePoint p : quasi_static.table.points) {
    p.line = ++line;
    sweep.table.points.push_back(p);
  }
  sweep.runs.insert(sweep.runs.end(), quasi_static.runs.begin(), quasi_static.runs.end());
  return sweep;
}

Law exact_law(const SyntheticTruth& t) {
  Law law;
  law.phi = t.phi;
  law.gamma_tilde_min = t.gamma_tilde.front();
  law.gamma_tilde_max = t.gamma_tilde.back();
  for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) law.hb[index(q)].emplace();
  for (std::size_t j = 0; j < t.phi.size(); ++j) {
    law.modulus.push_back({t.modulus[j], 0.03 * t.modulus[j]});
    law.yield_strain.push_back({t.yield_strain[j], 0.03 * t.yield_strain[j]});
    for (Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2}) {
      const double yield = t.value(j, q, 0.0);
      const double slope = (t.value(j, q, 1e-4) - yield) / std::sqrt(1e-4);
      HbLaw& hb = *law.hb[index(q)];
      hb.yield.push_back({yield, 0.01 * std::abs(yield)});
      hb.consistency.push_back({slope, 0.1 * std::abs(slope)});
      hb.exponent.push_back({0.5, 0.01});
      hb.correlation.push_back(0.99);
    }
  }
  law.k[0] = Estimate{t.k, 1.0};
  law.mean_exponent = {0.5, 0.001};
  validate(law, "exact");
  return law;
}

}  // namespace softglass::bridge::testing
