#include "macro/exact/channel.h"

#include <algorithm>
#include <cmath>

#include "macro/exact/rate_moment.h"

namespace softglass::macro::exact {

double wall_stress(const PlaneChannel& channel) {
  return channel.pressure_gradient * channel.half_height;
}

double plug_half_width(LawRef law, const PlaneChannel& channel) {
  return std::min(law->yield_stress() / channel.pressure_gradient, channel.half_height);
}

namespace {

// V_s(τ_w) of a slipping wall, 0 without slip.
double slip_velocity(const SlipLaw* wall, double wall_stress) {
  return wall ? wall->velocity(wall_stress) : 0.0;
}

}  // namespace

double flow_rate(LawRef law, const PlaneChannel& channel, const SlipLaw* wall) {
  const double G = channel.pressure_gradient, tau_w = wall_stress(channel);
  return 2.0 * channel.half_height * slip_velocity(wall, tau_w) +
         2.0 / (G * G) * rate_moment(*law, 1, 0.0, tau_w);
}

double velocity(LawRef law, const PlaneChannel& channel, double y, const SlipLaw* wall) {
  const double G = channel.pressure_gradient, tau_w = wall_stress(channel);
  return slip_velocity(wall, tau_w) + rate_moment(*law, 0, G * std::abs(y), tau_w) / G;
}

double flow_rate(const RegularisedLaw& law, const PlaneChannel& channel) {
  const double G = channel.pressure_gradient;
  return 2.0 / (G * G) * rate_moment(law, 1, 0.0, wall_stress(channel));
}

double velocity(const RegularisedLaw& law, const PlaneChannel& channel, double y) {
  const double G = channel.pressure_gradient;
  return rate_moment(law, 0, G * std::abs(y), wall_stress(channel)) / G;
}

}  // namespace softglass::macro::exact
