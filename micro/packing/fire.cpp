#include "micro/packing/fire.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::micro {

namespace {
// FIRE 2.0 parameters (Guénolé et al. 2020, Table 1).
constexpr int kDelay = 20;
constexpr double kGrow = 1.1, kShrink = 0.5;
constexpr double kAlphaStart = 0.25, kAlphaShrink = 0.99;
constexpr double kMinStepFraction = 0.02;

double stiffness_bound(const ContactField& field) {
  double worst = 0.0;
  for (double k : field.stiffness_sum) worst = std::max(worst, 2.0 * k);
  return worst;
}
}  // namespace

void FireSettings::validate() const {
  require(force_tolerance > 0.0 && force_tolerance < 1.0,
          fmt::format("force tolerance = {} is outside (0, 1)", force_tolerance));
  require(max_iterations > 0, "the minimiser needs at least one iteration");
  require(step_fraction > 0.0 && step_fraction < 2.0,
          fmt::format("FIRE step fraction = {} is outside (0, 2)", step_fraction));
  require(unjammed_force >= 0.0, fmt::format("unjammed force = {} is negative", unjammed_force));
}

double force_residual(const ContactField& field) {
  if (field.contact_count == 0 || field.force_magnitude_sum == 0.0) return 0.0;
  double worst = 0.0;
  for (const Vec3& f : field.force) worst = std::max(worst, f.squaredNorm());
  const double mean_contact_force =
      field.force_magnitude_sum / static_cast<double>(field.contact_count);
  return std::sqrt(worst) / mean_contact_force;
}

FireResult minimise_fire(ContactSystem& system, const FireSettings& settings) {
  settings.validate();
  const std::size_t n = system.size();
  FireResult result;
  auto& v = system.particles().velocity;
  std::fill(v.begin(), v.end(), Vec3::Zero());

  system.ensure_neighbours();
  const ContactField* field = &system.compute_forces();
  double dt_max = settings.step_fraction / std::sqrt(std::max(stiffness_bound(*field), 1e-300));
  double dt = 0.1 * dt_max;
  double alpha = kAlphaStart;
  int positive = 0;

  for (std::size_t it = 0;; ++it) {
    result.residual = force_residual(*field);
    result.unjammed = field->force_magnitude_sum <
                      settings.unjammed_force * static_cast<double>(field->contact_count);
    if (result.residual <= settings.force_tolerance || result.unjammed) {
      result.converged = true;
      break;
    }
    if (it == settings.max_iterations) break;
    result.iterations = it + 1;

    const auto& force = field->force;
    double power = 0.0;
    for (std::size_t a = 0; a < n; ++a) power += force[a].dot(v[a]);
    if (power > 0.0) {
      if (++positive > kDelay) {
        dt = std::min(dt * kGrow, dt_max);
        alpha *= kAlphaShrink;
      }
    } else {
      positive = 0;
      if (it >= static_cast<std::size_t>(kDelay)) {
        dt = std::max(dt * kShrink, kMinStepFraction * dt_max);
        alpha = kAlphaStart;
      }
      // Step back half a step and stop.
      system.move(-0.5 * dt, v);
      std::fill(v.begin(), v.end(), Vec3::Zero());
    }

    // Semi-implicit Euler with FIRE mixing.
    double vnorm2 = 0.0, fnorm2 = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      v[a] += dt * force[a];
      vnorm2 += v[a].squaredNorm();
      fnorm2 += force[a].squaredNorm();
    }
    const double mix = fnorm2 > 0.0 ? alpha * std::sqrt(vnorm2 / fnorm2) : 0.0;
    double vmax2 = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      v[a] = (1.0 - alpha) * v[a] + mix * force[a];
      vmax2 = std::max(vmax2, v[a].squaredNorm());
    }
    system.ensure_neighbours(dt * std::sqrt(vmax2));  // may reorder; v moves along
    system.move(dt, v);
    field = &system.compute_forces();
    dt_max = settings.step_fraction / std::sqrt(std::max(stiffness_bound(*field), 1e-300));
  }

  result.energy = system.compute_forces({.energy = true}).energy;
  std::fill(v.begin(), v.end(), Vec3::Zero());
  return result;
}

}  // namespace softglass::micro
