#include "macro/exact/pipe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "macro/exact/rate_moment.h"

namespace softglass::macro::exact {

double wall_stress(const Pipe& pipe) { return 0.5 * pipe.pressure_gradient * pipe.radius; }

double plug_radius(LawRef law, const Pipe& pipe) {
  return std::min(2.0 * law->yield_stress() / pipe.pressure_gradient, pipe.radius);
}

double flow_rate(LawRef law, const Pipe& pipe, const SlipLaw* wall) {
  const double G = pipe.pressure_gradient, R = pipe.radius, tau_w = wall_stress(pipe);
  const double slip = wall ? std::numbers::pi * R * R * wall->velocity(tau_w) : 0.0;
  return slip + 8.0 * std::numbers::pi / (G * G * G) * rate_moment(*law, 2, 0.0, tau_w);
}

double velocity(LawRef law, const Pipe& pipe, double r) {
  const double G = pipe.pressure_gradient;
  return 2.0 / G * rate_moment(*law, 0, 0.5 * G * r, wall_stress(pipe));
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
