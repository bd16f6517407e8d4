#include "macro/app/measured_torques.h"

#include <fmt/format.h>

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
  require(m.angular_velocity.size() >= 2,
          fmt::format("curve '{}': {} point(s) with shear rate in [{:g}, {:g}] 1/s; a comparison "
                      "needs at least 2",
                      curve.label, m.angular_velocity.size(), min_rate, max_rate));
  // Repeated rates (a down and an up sweep) stay: each is compared on its own.
  return m;
}

}  // namespace softglass::macro::app
