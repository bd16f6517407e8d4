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
  std::vector<const StatePoint*> points;
  for (const StatePoint& p : table.points) points.push_back(&p);
  std::sort(points.begin(), points.end(), [](const StatePoint* a, const StatePoint* b) {
    return a->phi < b->phi || (a->phi == b->phi && a->gamma_tilde < b->gamma_tilde);
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
  for (const StatePoint* p : points) {
    if (sweep.groups.empty() || p->phi - sweep.groups.back().phi > kSamePhi) {
      if (!sweep.groups.empty()) close_group();
      PhiGroup& g = sweep.groups.emplace_back();
      g.phi = p->phi;
      for (Quantity q : kAllQuantities)
        if (table.present[index(q)]) g.curves[index(q)].emplace();
    }
    PhiGroup& g = sweep.groups.back();
    if (p->converged && *p->converged < p->packings) {
      sweep.unconverged.push_back(fmt::format("phi = {}, gamma~ = {:.3g}: {} of {}", p->phi,
                                              p->gamma_tilde, *p->converged, p->packings));
    }
    if (p->gamma_tilde == 0.0) {
      if (g.quasi_static) {  // φ within 1e-9 of each other are one φ
        throw InputError(fmt::format(
            "{}, line {}: a second quasi-static row (gamma~ = 0) for phi = {} (line {})",
            table.source, p->line, g.phi, g.quasi_static->line));
      }
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
