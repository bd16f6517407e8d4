#include "macro/app/measured_torques.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::macro::app {

MeasuredTorques measured_torques(const RheometerCurve& curve, const InstrumentConstants& constants,
                                 double min_rate, double max_rate) {
  const bool has_omega = curve.has(Measured::angular_velocity);
  const bool has_rate = curve.has(Measured::shear_rate);
  const bool has_torque = curve.has(Measured::torque);
  const bool has_stress = curve.has(Measured::stress);
  MeasuredTorques m;
  m.label = curve.label;
  if (!has_omega) {
    m.conversions.push_back(fmt::format("angular velocity = shear rate / {:.6g} 1/rad ({})",
                                        constants.strain_constant, constants.convention));
  }
  if (!has_torque) {
    m.conversions.push_back(fmt::format("torque = stress / {:.6g} Pa/(N m) ({})",
                                        constants.stress_constant, constants.convention));
  }
  if (curve.has(Measured::normal_force)) m.normal_force.emplace();
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const double omega = has_omega ? curve[Measured::angular_velocity][i]
                                   : curve[Measured::shear_rate][i] / constants.strain_constant;
    const double rate =
        has_rate ? curve[Measured::shear_rate][i] : constants.strain_constant * omega;
    if (rate < min_rate || rate > max_rate) {
      ++m.left_out;
      continue;
    }
    const double torque = has_torque ? curve[Measured::torque][i]
                                     : curve[Measured::stress][i] / constants.stress_constant;
    m.angular_velocity.push_back(omega);
    m.shear_rate.push_back(rate);
    m.torque.push_back(torque);
    m.stress.push_back(has_stress ? curve[Measured::stress][i]
                                  : constants.stress_constant * torque);
    if (m.normal_force) m.normal_force->push_back(curve[Measured::normal_force][i]);
  }
  m.stress_per_torque = constants.stress_constant;
  if (has_stress && has_torque) {
    std::vector<double> ratios;
    for (std::size_t i = 0; i < m.torque.size(); ++i) ratios.push_back(m.stress[i] / m.torque[i]);
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    if (!ratios.empty()) m.stress_per_torque = ratios[ratios.size() / 2];
    if (std::abs(m.stress_per_torque / constants.stress_constant - 1.0) > 0.01) {
      m.conversions.push_back(fmt::format(
          "predicted stress = predicted torque x {:.6g} Pa/(N m), the file's own stress per "
          "torque ({} the {:.6g} of {}: the instrument's end-effect correction or constants)",
          m.stress_per_torque, m.stress_per_torque < constants.stress_constant ? "below" : "above",
          constants.stress_constant, constants.convention));
    }
  }
  require(m.angular_velocity.size() >= 2,
          fmt::format("curve '{}': {} point(s) with shear rate in [{:g}, {:g}] 1/s; a comparison "
                      "needs at least 2",
                      curve.label, m.angular_velocity.size(), min_rate, max_rate));
  // Repeated rates (a down and an up sweep) stay: each is compared on its own.
  return m;
}

MeasuredTorques thinned(const MeasuredTorques& m, std::size_t max_points) {
  const std::size_t n = m.angular_velocity.size();
  if (n <= max_points) return m;
  MeasuredTorques kept{
      .label = m.label,
      .normal_force = m.normal_force ? std::optional(std::vector<double>{}) : std::nullopt,
      .stress_per_torque = m.stress_per_torque,
      .conversions = m.conversions,
      .left_out = m.left_out,
      .thinned_out = n - max_points};
  for (std::size_t k = 0; k < max_points; ++k) {
    const std::size_t i = (k * (n - 1) + (max_points - 1) / 2) / (max_points - 1);
    kept.angular_velocity.push_back(m.angular_velocity[i]);
    kept.shear_rate.push_back(m.shear_rate[i]);
    kept.torque.push_back(m.torque[i]);
    kept.stress.push_back(m.stress[i]);
    if (m.normal_force) kept.normal_force->push_back((*m.normal_force)[i]);
  }
  return kept;
}

}  // namespace softglass::macro::app
