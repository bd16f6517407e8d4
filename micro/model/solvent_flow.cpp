#include "micro/model/solvent_flow.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::micro {

SolventReference parse_solvent_reference(const std::string& name) {
  if (name == "affine") return SolventReference::affine;
  if (name == "local mean") return SolventReference::local_mean;
  throw InputError(fmt::format("solvent flow '{}' is unknown; allowed: {}", name,
                               solvent_reference_names()));
}

std::string to_string(SolventReference reference) {
  return reference == SolventReference::affine ? "affine" : "local mean";
}

std::string solvent_reference_names() {
  return "affine|local mean";
}

SolventFlow SolventFlow::local_mean(double lower, double upper, double spacing) {
  require(std::isfinite(lower) && std::isfinite(upper) && upper > lower && spacing > 0.0,
          fmt::format("solvent flow: the gap ({}, {}) or the node spacing {} is empty", lower,
                      upper, spacing));
  // Nodes at the centres of equal slabs about `spacing` thick.
  const auto nodes = static_cast<std::size_t>(std::max(2.0, std::round((upper - lower) / spacing)));
  SolventFlow flow;
  flow.spacing_ = (upper - lower) / static_cast<double>(nodes);
  flow.lower_ = lower + 0.5 * flow.spacing_;
  flow.profile_.assign(nodes, 0.0);
  return flow;
}

SolventFlow::Weights SolventFlow::weights(double y) const {
  const double t = (y - lower_) / spacing_;
  const double last = static_cast<double>(profile_.size() - 1);
  if (!(t > 0.0)) return {0, 0.0};
  if (t >= last) return {profile_.size() - 2, 1.0};
  const auto k = static_cast<std::size_t>(t);
  return {k, t - static_cast<double>(k)};
}

double SolventFlow::velocity(double y, double rate) const {
  if (affine() || !filled_) return 0.0;
  const Weights w = weights(y);
  return (1.0 - w.s) * profile_[w.k] + w.s * profile_[w.k + 1] - rate * y;
}

void SolventFlow::update(std::span<const Vec3> x, std::span<const Vec3> v,
                         std::span<const double> friction, double rate) {
  if (affine()) return;
  sum_.assign(profile_.size(), 0.0);
  weight_.assign(profile_.size(), 0.0);
  for (std::size_t a = 0; a < x.size(); ++a) {
    const Weights w = weights(x[a].y());
    const double lower = (1.0 - w.s) * friction[a], upper = w.s * friction[a];
    const double u = rate * x[a].y() + v[a].x();
    sum_[w.k] += lower * u;
    weight_[w.k] += lower;
    sum_[w.k + 1] += upper * u;
    weight_[w.k + 1] += upper;
  }
  for (std::size_t k = 0; k < profile_.size(); ++k)
    if (weight_[k] > 0.0) profile_[k] = sum_[k] / weight_[k];
    else if (!filled_) profile_[k] = rate * (lower_ + spacing_ * static_cast<double>(k));
  filled_ = true;
}

}  // namespace softglass::micro
