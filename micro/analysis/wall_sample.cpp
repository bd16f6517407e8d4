#include "micro/analysis/wall_sample.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/errors.h"

namespace softglass::micro {

void WallSampleSettings::validate() const {
  require(central_fraction > 0.0 && central_fraction <= 1.0,
          fmt::format("walls: central fraction = {} is outside (0, 1]", central_fraction));
  require(bins >= 2 && bins <= 10000,
          fmt::format("walls: profile bins = {} is outside [2, 10000]", bins));
}

namespace {
// Length of the segment between heights y0 and y1 inside (low, high).
double inside(double y0, double y1, double low, double high) {
  return std::max(0.0, std::min(std::max(y0, y1), high) - std::max(std::min(y0, y1), low));
}
}  // namespace

WallSample measure_wall_sample(const OverdampedShear& flow, const WallSampleSettings& settings) {
  const ContactSystem& system = flow.system();
  const Walls& walls = system.walls();
  if (!walls.present()) throw std::logic_error("measure_wall_sample: the system has no walls");
  const ContactField& field = system.forces();
  const ContactList& c = field.contacts;
  const WallContacts& wc = field.walls;
  const Particles& p = system.particles();
  const std::size_t n = p.size();
  const ShearModel& model = flow.model();
  const double rate = flow.rate(), area = system.box().side() * system.box().side();
  const double gap = walls.gap();
  const double y_a = walls.lower + 0.5 * (1.0 - settings.central_fraction) * gap;
  const double y_b = walls.upper - 0.5 * (1.0 - settings.central_fraction) * gap;
  WallSample s;

  // The frictions ζ (per particle, in the engine's order) and the films' and
  // dashpots' forces at the evaluated velocities.
  std::vector<double> friction(n);
  for (std::size_t a = 0; a < n; ++a) friction[a] = model.friction(p.radius[a]);
  const EhdDrag drag(model.drag);
  std::vector<Vec3> pair_force(c.size()), wall_force(wc.size());
  drag.virial(c, model.gamma_tilde, rate, p.velocity, {}, friction, pair_force);
  drag.wall_drag(wc, model.gamma_tilde, rate, p.velocity, wall_force);

  for (std::size_t k = 0; k < wc.size(); ++k) {
    const bool lower = wc.normal_y[k] > 0.0;
    (lower ? s.wall_stress_lower : s.wall_stress_upper) += (lower ? -1.0 : 1.0) * wall_force[k].x();
    (lower ? s.normal_stress_lower : s.normal_stress_upper) += wc.force[k];
    (lower ? s.contacts_lower : s.contacts_upper) += 1.0;
  }
  for (double* q : {&s.wall_stress_lower, &s.wall_stress_upper, &s.normal_stress_lower,
                    &s.normal_stress_upper, &s.contacts_lower, &s.contacts_upper})
    *q /= area;

  // Central-slab virial: pair c joins x_i and x_j = x_i − d.
  const double volume = area * (y_b - y_a);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3& d = c.separation[k];
    const double yi = p.position[c.i[k]].y();
    const double share = inside(yi, yi - d.y(), y_a, y_b);
    if (share == 0.0) continue;
    const double dy_in = std::copysign(share, d.y());
    const double elastic_x = c.force[k] * d.x() / d.norm();
    s.bulk_stress_elastic -= dy_in * elastic_x / volume;
    s.bulk_stress -= dy_in * (elastic_x + pair_force[k].x()) / volume;
  }

  // The reservoir friction's share, the profile and the central fit.
  const StokesFriction& stokes = model.drag.stokes;
  s.profile.assign(settings.bins, 0.0);
  s.profile_count.assign(settings.bins, 0.0);
  double sy = 0, su = 0, syy = 0, syu = 0, count = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const double y = p.position[a].y();
    const double u = rate * y + p.velocity[a].x();
    const double above = std::clamp((y_b - y) / (y_b - y_a), 0.0, 1.0);
    const double slip_past_solvent = p.velocity[a].x() - flow.solvent_flow().velocity(y, rate);
    const double reservoir = stokes.reservoir(friction[a]) * slip_past_solvent / area;
    s.reservoir_term += reservoir * above;
    s.reservoir_total += reservoir;
    const double t = (y - walls.lower) / gap * static_cast<double>(settings.bins);
    const auto bin = static_cast<std::size_t>(
        std::clamp(std::floor(t), 0.0, static_cast<double>(settings.bins - 1)));
    s.profile[bin] += u;
    s.profile_count[bin] += 1.0;
    if (y > y_a && y < y_b) sy += y, su += u, syy += y * y, syu += y * u, count += 1.0;
  }
  for (std::size_t b = 0; b < settings.bins; ++b)
    s.profile[b] = s.profile_count[b] > 0.0 ? s.profile[b] / s.profile_count[b]
                                            : std::numeric_limits<double>::quiet_NaN();
  const double spread = syy - sy * sy / std::max(count, 1.0);
  s.bulk_rate = count >= 2.0 && spread > 0.0 ? (syu - sy * su / count) / spread
                                             : std::numeric_limits<double>::quiet_NaN();
  s.slip_velocity = 0.5 * (rate - s.bulk_rate) * gap;
  return s;
}

}  // namespace softglass::micro
