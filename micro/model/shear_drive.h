// The imposed shear as a function of time: steady, or oscillatory.
//
// Time t is measured in units of 1/γ̇_ref, where γ̇_ref is the run's reference
// rate — the shear rate of a steady run, the peak rate γ0 ω of an oscillatory
// one — so that the model's γ̃ = γ̇_ref η_s/E* sets the frictions and the EHD
// drag exactly as in steady shear (overdamped_shear.h). The drive gives the
// strain γ(t) of the Lees–Edwards cell and the rate c(t) = γ̇(t)/γ̇_ref that
// multiplies the affine flow u∞ = c(t) γ̇_ref y e_x:
//
//   steady         γ(t) = t,                 c(t) = 1;
//   oscillatory    γ(t) = γ0 sin(t/γ0),       c(t) = cos(t/γ0),
//
// the second being γ0 sin ωt in physical time t/γ̇_ref, since ω t/γ̇_ref = t/γ0
// with γ̇_ref = γ0 ω: one cycle lasts 2π γ0 in these units, and the run starts
// at strain 0 with the rate at its peak.
#pragma once

#include <cmath>
#include <numbers>

namespace softglass::micro {

class ShearDrive {
 public:
  /// γ(t) = t: the paper's steady shear.
  static ShearDrive steady() { return ShearDrive(0.0); }
  /// γ(t) = γ0 sin(t/γ0); `amplitude` γ0 > 0.
  static ShearDrive oscillatory(double amplitude) { return ShearDrive(amplitude); }

  bool is_steady() const { return amplitude_ == 0.0; }
  double amplitude() const { return amplitude_; }
  /// One cycle (oscillatory only), in units of time.
  double period() const { return 2.0 * std::numbers::pi * amplitude_; }

  double strain(double t) const { return is_steady() ? t : amplitude_ * std::sin(t / amplitude_); }
  double rate(double t) const { return is_steady() ? 1.0 : std::cos(t / amplitude_); }
  /// γ(t + dt) − γ(t); exactly dt for steady shear, so that a steady run
  /// advances its cell by its steps themselves.
  double strain_increment(double t, double dt) const {
    return is_steady() ? dt : strain(t + dt) - strain(t);
  }

 private:
  explicit ShearDrive(double amplitude) : amplitude_(amplitude) {}
  double amplitude_;
};

}  // namespace softglass::micro
