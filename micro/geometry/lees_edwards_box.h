// The periodic simulation cell under simple shear.
//
// Axes: x = flow, y = gradient, z = vorticity. The imposed flow is u∞ = γ̇ y e_x.
// Lees–Edwards images: the copy of the cell above (y + L) is shifted in x by the
// image offset δ = (γ mod 1) L and moves faster by γ̇ L. Positions live in the
// primary cell [0, L)³; pair vectors are taken to the nearest image.
//
// The accumulated strain is stored as an integer part and a fraction, so that the
// offset keeps full precision after any number of box lengths of shear.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace softglass::micro {

using Vec3 = Eigen::Vector3d;

class LeesEdwardsBox {
 public:
  explicit LeesEdwardsBox(double side = 1.0);

  double side() const { return side_; }
  double volume() const { return side_ * side_ * side_; }

  /// Total accumulated strain γ.
  double strain() const { return static_cast<double>(whole_strain_) + strain_fraction_; }
  /// x shift of the image above the cell, δ ∈ [0, L).
  double image_offset() const { return offset_; }

  void set_strain(double strain);
  void advance_strain(double increment);

  /// Maps a position into the primary cell, applying the image offset when it
  /// crosses the gradient (y) boundary. A particle moves by far less than L per
  /// step, so the loops run at most once in practice (no rounding calls).
  void wrap(Vec3& x) const {
    while (x.y() >= side_) {
      x.y() -= side_;
      x.x() -= offset_;
    }
    while (x.y() < 0.0) {
      x.y() += side_;
      x.x() += offset_;
    }
    wrap_periodic(x.x());
    wrap_periodic(x.z());
  }

  /// Nearest-image separation d = x_α − x_β for any two positions (wrapped or
  /// not). Used when building neighbour lists and in tests; the force loop uses
  /// the images stored in the list instead.
  Vec3 minimum_image(Vec3 d) const {
    while (d.y() > half_) {
      d.y() -= side_;
      d.x() -= offset_;
    }
    while (d.y() < -half_) {
      d.y() += side_;
      d.x() += offset_;
    }
    while (d.x() > half_) d.x() -= side_;
    while (d.x() < -half_) d.x() += side_;
    while (d.z() > half_) d.z() -= side_;
    while (d.z() < -half_) d.z() += side_;
    return d;
  }

 private:
  void update_offset();
  void wrap_periodic(double& c) const {
    while (c >= side_) c -= side_;
    while (c < 0.0) c += side_;
  }

  double side_;
  double half_;
  std::int64_t whole_strain_ = 0;
  double strain_fraction_ = 0.0;  // in [0, 1)
  double offset_ = 0.0;
};

}  // namespace softglass::micro
