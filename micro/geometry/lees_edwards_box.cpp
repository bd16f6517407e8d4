#include "micro/geometry/lees_edwards_box.h"

#include <stdexcept>

namespace softglass::micro {

LeesEdwardsBox::LeesEdwardsBox(double side) : side_(side), half_(0.5 * side) {
  if (!(side > 0.0) || !std::isfinite(side))
    throw std::invalid_argument("box side must be positive");
}

void LeesEdwardsBox::set_strain(double strain) {
  const double whole = std::floor(strain);
  whole_strain_ = static_cast<std::int64_t>(whole);
  strain_fraction_ = strain - whole;
  update_offset();
}

void LeesEdwardsBox::advance_strain(double increment) {
  strain_fraction_ += increment;
  const double carry = std::floor(strain_fraction_);
  whole_strain_ += static_cast<std::int64_t>(carry);
  strain_fraction_ -= carry;
  update_offset();
}

void LeesEdwardsBox::update_offset() {
  offset_ = strain_fraction_ * side_;
  if (offset_ >= side_) offset_ = 0.0;
}

}  // namespace softglass::micro
