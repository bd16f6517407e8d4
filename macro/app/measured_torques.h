// A measured rheometer curve as angular velocities and torques, the quantities
// the finite-element scene predicts.
//
// Instruments export what they measure (angular velocity Ω, torque M, normal
// force F) and what their software derives from it (shear rate γ̇, stress τ)
// with the geometry's standard constants (scene.h, InstrumentConstants). Where
// Ω or M is missing it is recovered with the same constants: Ω = γ̇ / c_γ and
// M = τ / c_τ. Every conversion made is listed, so the report says what was
// measured and what was derived.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/measured_curves.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

struct MeasuredTorques {
  std::string label;                                  // the curve's
  std::vector<double> angular_velocity{};             // Ω [rad/s], increasing
  std::vector<double> shear_rate{};                   // γ̇ [1/s] as reported (or c_γ Ω)
  std::vector<double> torque{};                       // M [N m]
  std::vector<double> stress{};                       // τ [Pa] as reported (or c_τ M)
  std::optional<std::vector<double>> normal_force{};  // F [N] when measured
  /// τ/M as the file has it: with stress and torque both measured, the median
  /// of their ratios (the instrument's own constant, end-effect correction
  /// included); otherwise the c_τ of the conversion. Predicted stresses are
  /// predicted torques times this, so both stresses compare as the torques do.
  double stress_per_torque = 0.0;
  std::vector<std::string> conversions{};  // one line per derived quantity
  std::size_t left_out = 0;                // points outside the rate window
  std::size_t thinned_out = 0;             // points left out by thinned()
};

/// The points of `curve` whose shear rate (reported, or c_γ Ω) lies in
/// [min_rate, max_rate]. InputError when fewer than 2 points remain.
MeasuredTorques measured_torques(const RheometerCurve& curve, const InstrumentConstants& constants,
                                 double min_rate, double max_rate);

/// At most `max_points` (>= 2) of the points, evenly spaced in their order,
/// the first and the last kept (measured curves are spaced evenly in log Ω,
/// so the kept ones are too).
MeasuredTorques thinned(const MeasuredTorques& m, std::size_t max_points);

}  // namespace softglass::macro::app
