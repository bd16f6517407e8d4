#include "bridge/sweep/resampling.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numeric>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// A bias-corrected bootstrap mean of `samples` centred on `centre` (see the header).
double redraw_mean(const std::vector<double>& samples, double centre, std::mt19937_64& rng,
                   double scale = 1.0) {
  const std::size_t k = samples.size();
  std::uniform_int_distribution<std::size_t> pick(0, k - 1);
  double sum = 0.0;
  for (std::size_t i = 0; i < k; ++i) sum += samples[pick(rng)];
  const double kd = static_cast<double>(k);
  return centre + scale * std::sqrt(kd / (kd - 1.0)) * (sum / kd - mean(samples));
}

class ParametricResampler : public Resampler {
 public:
  explicit ParametricResampler(const Sweep& sweep) : sweep_(sweep) {}

  Sweep draw(std::mt19937_64& rng) const override {
    std::normal_distribution<double> normal;
    Sweep replicate = sweep_;
    for (PhiGroup& g : replicate.groups) {
      g.modulus.value += g.modulus.error * normal(rng);
      for (auto& curve : g.curves) {
        if (!curve) continue;
        for (std::size_t i = 0; i < curve->size(); ++i) curve->y[i] += curve->se[i] * normal(rng);
      }
    }
    return replicate;
  }
  std::string description() const override {
    return "parametric bootstrap: Gaussian redraws with the table's standard errors";
  }

 private:
  Sweep sweep_;
};

// The runs of one φ: per state point and quantity the K run values, and G0 per seed.
struct GroupRuns {
  std::vector<PerQuantity<std::vector<double>>> points;
  std::vector<double> moduli;  // one per distinct packing
};

// `redrawn[q]`: the runs hold quantity q (packing redraws); otherwise its values
// are Gaussian redraws with the smoothed standard errors, as in the parametric
// bootstrap (f_m from a structure table has no per-run values).
class PackingResampler : public Resampler {
 public:
  PackingResampler(const Sweep& sweep, std::vector<GroupRuns> runs,
                   std::array<bool, kQuantities> redrawn)
      : sweep_(sweep), runs_(std::move(runs)), redrawn_(redrawn) {}

  Sweep draw(std::mt19937_64& rng) const override {
    Sweep replicate = sweep_;
    for (std::size_t j = 0; j < replicate.groups.size(); ++j) {
      PhiGroup& g = replicate.groups[j];
      const GroupRuns& r = runs_[j];
      g.modulus.value = redraw_mean(r.moduli, sweep_.groups[j].modulus.value, rng);
      for (Quantity q : kAllQuantities) {
        if (!g.curves[index(q)]) continue;
        Curve& curve = *g.curves[index(q)];
        const Curve& original = *sweep_.groups[j].curves[index(q)];
        std::normal_distribution<double> normal;
        for (std::size_t i = 0; i < curve.size(); ++i) {
          curve.y[i] =
              redrawn_[index(q)]
                  ? redraw_mean(*r.points[i][index(q)], original.y[i], rng,
                                original.se[i] / (*sweep_.groups[j].table_errors[index(q)])[i])
                  : original.y[i] + original.se[i] * normal(rng);
        }
      }
    }
    return replicate;
  }
  std::string description() const override {
    std::string text = "packing bootstrap: packings redrawn with replacement at every state point";
    for (Quantity q : kAllQuantities) {
      if (sweep_.present[index(q)] && !redrawn_[index(q)])
        text += fmt::format(" ({}: Gaussian redraws, no per-run values)", column_name(q));
    }
    return text;
  }

 private:
  Sweep sweep_;
  std::vector<GroupRuns> runs_;
  std::array<bool, kQuantities> redrawn_;
};

// The index of γ̃ in a group's rates, or size().
std::size_t find_rate(const PhiGroup& g, double gamma_tilde) {
  const std::vector<double>& x = g.curves[index(Quantity::sigma)]->x;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i] - gamma_tilde) <= 1e-9 * x[i]) return i;
  return x.size();
}

}  // namespace

std::unique_ptr<Resampler> make_parametric_resampler(const Sweep& sweep) {
  return std::make_unique<ParametricResampler>(sweep);
}

std::unique_ptr<Resampler> make_packing_resampler(const Sweep& sweep,
                                                  const std::vector<PackingRun>& runs,
                                                  const std::string& source) {
  std::vector<GroupRuns> groups(sweep.groups.size());
  std::vector<std::map<std::uint64_t, std::vector<double>>> moduli(sweep.groups.size());
  for (std::size_t j = 0; j < sweep.groups.size(); ++j)
    groups[j].points.resize(sweep.groups[j].lines.size());

  // Quantities the runs hold: the same for every run (one header).
  std::array<bool, kQuantities> redrawn{};
  for (Quantity q : kAllQuantities) {
    redrawn[index(q)] = !runs.empty() && runs.front().values[index(q)].has_value();
    if (redrawn[index(q)] && !sweep.present[index(q)]) {
      throw InputError(
          fmt::format("{}: column '{}' is not in the flow-curve table", source, column_name(q)));
    }
  }
  if (!redrawn[index(Quantity::sigma)]) throw InputError(source + ": column 'sigma' is missing");
  for (Quantity q : {Quantity::N1, Quantity::N2}) {
    if (sweep.present[index(q)] && !redrawn[index(q)]) {
      throw InputError(
          fmt::format("{}: column '{}' is in the flow-curve table only", source, column_name(q)));
    }
  }

  // Quasi-static runs (γ̃ = 0) are not resampled, as they are not fitted
  // (sweep.h), but are checked against their rows like the others.
  std::vector<std::vector<double>> quasi_static(sweep.groups.size());
  for (const PackingRun& run : runs) {
    const std::size_t j = find_group(sweep, run.phi);
    const bool at_rest = run.gamma_tilde == 0.0;
    bool known = j < sweep.groups.size();
    std::size_t i = 0;
    if (known && at_rest) known = sweep.groups[j].quasi_static.has_value();
    if (known && !at_rest) {
      i = find_rate(sweep.groups[j], run.gamma_tilde);
      known = i < sweep.groups[j].lines.size();
    }
    if (!known) {
      throw InputError(
          fmt::format("{}, line {}: phi = {}, gamma~ = {} is not a state point of "
                      "the flow-curve table",
                      source, run.line, run.phi, run.gamma_tilde));
    }
    if (at_rest) {
      quasi_static[j].push_back(*run.values[index(Quantity::sigma)]);
      continue;
    }
    for (Quantity q : kAllQuantities) {
      if (!redrawn[index(q)]) continue;
      auto& samples = groups[j].points[i][index(q)];
      if (!samples) samples.emplace();
      samples->push_back(*run.values[index(q)]);
    }
    moduli[j][run.seed].push_back(run.modulus);
  }

  for (std::size_t j = 0; j < sweep.groups.size(); ++j) {
    const PhiGroup& g = sweep.groups[j];
    for (std::size_t i = 0; i < g.lines.size(); ++i) {
      const std::size_t k = groups[j].points[i][0] ? groups[j].points[i][0]->size() : 0;
      if (k != g.packings[i] || k < 2) {
        throw InputError(fmt::format(
            "{}: {} run(s) at phi = {}, gamma~ = {} where the flow-curve table (line {}) "
            "averages {} packings; the packing bootstrap needs the runs of every state point, "
            "at least 2 (with one packing per state point leave out --packings: the errors then "
            "come from the table's standard errors)",
            source, k, g.phi, g.curves[index(Quantity::sigma)]->x[i], g.lines[i], g.packings[i]));
      }
      for (Quantity q : kAllQuantities) {
        if (!redrawn[index(q)]) continue;
        const Curve& c = *g.curves[index(q)];
        const double m = mean(*groups[j].points[i][index(q)]);
        if (std::abs(m - c.y[i]) > 0.01 * c.se[i]) {
          throw InputError(fmt::format(
              "{}: the runs at phi = {}, gamma~ = {} average {} = {:.6g}, the flow-curve table "
              "(line {}) says {:.6g}: are the two tables from the same sweep?",
              source, g.phi, c.x[i], column_name(q), m, g.lines[i], c.y[i]));
        }
      }
    }
    if (const auto& row = g.quasi_static) {
      const Estimate sigma = *row->values[index(Quantity::sigma)];
      const std::vector<double>& s = quasi_static[j];
      if (s.size() != row->packings || std::abs(mean(s) - sigma.value) > 0.01 * sigma.error) {
        throw InputError(fmt::format(
            "{}: {} quasi-static run(s) at phi = {}{} where the flow-curve table (line {}) "
            "averages {} packings to sigma = {:.6g}: are the two tables from the same sweep?",
            source, s.size(), g.phi,
            s.empty() ? "" : fmt::format(" average sigma = {:.6g}", mean(s)), row->line,
            row->packings, sigma.value));
      }
    }
    for (const auto& [seed, values] : moduli[j]) groups[j].moduli.push_back(mean(values));
    if (groups[j].moduli.size() < 2) {
      throw InputError(
          fmt::format("{}: phi = {} has G0 from {} packing(s); the packing "
                      "bootstrap needs at least 2",
                      source, g.phi, groups[j].moduli.size()));
    }
  }
  return std::make_unique<PackingResampler>(sweep, std::move(groups), redrawn);
}

}  // namespace softglass::bridge
