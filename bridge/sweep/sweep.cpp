#include "bridge/sweep/sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bridge/fit/error_model.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

constexpr double kSamePhi = 1e-9;

Estimate combine_moduli(std::vector<Estimate> rows) {
  std::sort(rows.begin(), rows.end(), [](const Estimate& a, const Estimate& b) {
    return a.value < b.value || (a.value == b.value && a.error < b.error);
  });
  rows.erase(std::unique(rows.begin(), rows.end(),
                         [](const Estimate& a, const Estimate& b) {
                           return a.value == b.value && a.error == b.error;
                         }),
             rows.end());
  double sum = 0.0, variance = 0.0;
  for (const Estimate& e : rows) {
    sum += e.value;
    variance += e.error * e.error;
  }
  const double n = static_cast<double>(rows.size());
  return {sum / n, std::sqrt(variance) / n};
}

}  // namespace

std::size_t Sweep::points() const {
  std::size_t n = 0;
  for (const PhiGroup& g : groups) n += g.curves[index(Quantity::sigma)]->size();
  return n;
}

std::size_t Sweep::quasi_static_points() const {
  return static_cast<std::size_t>(std::count_if(
      groups.begin(), groups.end(), [](const PhiGroup& g) { return g.quasi_static.has_value(); }));
}

std::size_t find_group(const Sweep& sweep, double phi) {
  for (std::size_t j = 0; j < sweep.groups.size(); ++j)
    if (std::abs(sweep.groups[j].phi - phi) <= kSamePhi) return j;
  return sweep.groups.size();
}

Sweep make_sweep(const FlowCurveTable& table) {
  // The rows by φ — rows within kSamePhi of the last are one φ — and within a
  // φ by γ̃, so that each curve increases in γ̃ and a rate appears once.
  std::vector<const StatePoint*> by_phi;
  for (const StatePoint& p : table.points) by_phi.push_back(&p);
  std::sort(by_phi.begin(), by_phi.end(),
            [](const StatePoint* a, const StatePoint* b) { return a->phi < b->phi; });
  std::vector<std::pair<std::size_t, const StatePoint*>> points;  // (φ group, row)
  for (std::size_t k = 0; k < by_phi.size(); ++k) {
    const bool same_phi = k > 0 && by_phi[k]->phi - by_phi[k - 1]->phi <= kSamePhi;
    points.emplace_back(k == 0 ? 0 : points.back().first + (same_phi ? 0 : 1), by_phi[k]);
  }
  std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return a.first < b.first ||
           (a.first == b.first && a.second->gamma_tilde < b.second->gamma_tilde);
  });

  Sweep sweep;
  sweep.present = table.present;
  std::vector<Estimate> moduli;
  const auto close_group = [&] {
    PhiGroup& g = sweep.groups.back();
    g.modulus = combine_moduli(moduli);
    moduli.clear();
    if (g.lines.size() < 4) {
      throw InputError(
          fmt::format("{}: phi = {} has {} shear rate(s); a Herschel-Bulkley fit needs at least 4",
                      table.source, g.phi, g.lines.size()));
    }
    for (Quantity q : kAllQuantities) {
      if (!g.curves[index(q)]) continue;
      g.table_errors[index(q)] = g.curves[index(q)]->se;
      smooth_errors(*g.curves[index(q)], g.packings);
    }
  };
  for (std::size_t k = 0; k < points.size(); ++k) {
    const StatePoint* p = points[k].second;
    const bool new_phi = k == 0 || points[k].first != points[k - 1].first;
    if (new_phi) {
      if (!sweep.groups.empty()) close_group();
      PhiGroup& g = sweep.groups.emplace_back();
      g.phi = p->phi;
      for (Quantity q : kAllQuantities)
        if (table.present[index(q)]) g.curves[index(q)].emplace();
    } else if (const StatePoint* before = points[k - 1].second;
               std::abs(p->gamma_tilde - before->gamma_tilde) <= 1e-9 * p->gamma_tilde) {
      throw InputError(
          fmt::format("{}, line {}: state point phi = {}, gamma~ = {} already on line {}",
                      table.source, p->line, p->phi, p->gamma_tilde, before->line));
    }
    PhiGroup& g = sweep.groups.back();
    if (p->converged && *p->converged < p->packings) {
      sweep.unconverged.push_back(fmt::format("phi = {}, gamma~ = {:.3g}: {} of {}", p->phi,
                                              p->gamma_tilde, *p->converged, p->packings));
    }
    if (p->gamma_tilde == 0.0) {
      g.quasi_static = *p;
      continue;
    }
    g.lines.push_back(p->line);
    g.packings.push_back(p->packings);
    moduli.push_back(p->modulus);
    for (Quantity q : kAllQuantities) {
      if (!table.present[index(q)]) continue;
      Curve& c = *g.curves[index(q)];
      c.x.push_back(p->gamma_tilde);
      c.y.push_back(p->values[index(q)]->value);
      c.se.push_back(p->values[index(q)]->error);
    }
  }
  close_group();
  return sweep;
}

}  // namespace softglass::bridge
