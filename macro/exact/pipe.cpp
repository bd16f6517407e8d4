#include "macro/exact/pipe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "macro/exact/rate_moment.h"

namespace softglass::macro::exact {

double wall_stress(const Pipe& pipe) { return 0.5 * pipe.pressure_gradient * pipe.radius; }

double plug_radius(const HerschelBulkley& law, const Pipe& pipe) {
  return std::min(2.0 * law.yield_stress / pipe.pressure_gradient, pipe.radius);
}

double flow_rate(const HerschelBulkley& law, const Pipe& pipe, const SlipLaw* wall) {
  const double tau_w = wall_stress(pipe), phi = law.yield_stress / tau_w;
  const double R = pipe.radius;
  const double slip = wall ? std::numbers::pi * R * R * wall->velocity(tau_w) : 0.0;
  if (phi >= 1.0) return slip;
  const double n = law.flow_index;
  const double bracket = (1.0 - phi) * (1.0 - phi) / (3.0 * n + 1.0) +
                         2.0 * phi * (1.0 - phi) / (2.0 * n + 1.0) + phi * phi / (n + 1.0);
  return slip + std::numbers::pi * R * R * R * std::pow(tau_w / law.consistency, 1.0 / n) * n *
         std::pow(1.0 - phi, (n + 1.0) / n) * bracket;
}

double velocity(const HerschelBulkley& law, const Pipe& pipe, double r) {
  const double G = pipe.pressure_gradient;
  return 2.0 / G * (law.rate_integral(wall_stress(pipe)) - law.rate_integral(0.5 * G * r));
}

double flow_rate(const RegularisedLaw& law, const Pipe& pipe) {
  const double G = pipe.pressure_gradient;
  return 8.0 * std::numbers::pi / (G * G * G) * rate_moment(law, 2, 0.0, wall_stress(pipe));
}

double velocity(const RegularisedLaw& law, const Pipe& pipe, double r) {
  const double G = pipe.pressure_gradient;
  return 2.0 / G * rate_moment(law, 0, 0.5 * G * r, wall_stress(pipe));
}

}  // namespace softglass::macro::exact
