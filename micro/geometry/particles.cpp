#include "micro/geometry/particles.h"

#include <algorithm>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace softglass::micro {

Particles::Particles(std::vector<Vec3> positions, std::vector<double> radii)
    : position(std::move(positions)), radius(std::move(radii)) {
  if (position.size() != radius.size()) {
    throw std::invalid_argument("positions and radii differ in length");
  }
  velocity.assign(position.size(), Vec3::Zero());
  label.resize(position.size());
  std::iota(label.begin(), label.end(), 0u);
}

double Particles::max_radius() const {
  return radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
}

double Particles::total_volume() const {
  double sum = 0.0;
  for (double r : radius) sum += r * r * r;
  return 4.0 / 3.0 * std::numbers::pi * sum;
}

namespace {
template <class T>
void apply(std::vector<T>& values, std::span<const std::uint32_t> order) {
  std::vector<T> permuted(values.size());
  for (std::size_t i = 0; i < order.size(); ++i) permuted[i] = values[order[i]];
  values.swap(permuted);
}
}  // namespace

void Particles::permute(std::span<const std::uint32_t> order) {
  if (order.size() != size()) throw std::invalid_argument("permutation has the wrong length");
  apply(position, order);
  apply(radius, order);
  apply(velocity, order);
  apply(label, order);
}

Particles Particles::in_label_order() const {
  std::vector<std::uint32_t> order(size());
  for (std::size_t i = 0; i < size(); ++i) order[label[i]] = static_cast<std::uint32_t>(i);
  Particles sorted = *this;
  sorted.permute(order);
  return sorted;
}

}  // namespace softglass::micro
