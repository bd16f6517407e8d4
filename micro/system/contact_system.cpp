#include "micro/system/contact_system.h"

#include <fmt/format.h>

#include "common/errors.h"

namespace softglass::micro {

ContactSystem::ContactSystem(Particles particles, LeesEdwardsBox box,
                             std::shared_ptr<const ContactLaw> law, double skin)
    : particles_(std::move(particles)), box_(box), law_(std::move(law)), neighbours_(skin) {
  for (auto& x : particles_.position) {
    if (!x.allFinite()) throw InputError("a particle position is not finite");
    box_.wrap(x);
  }
  for (double r : particles_.radius) {
    if (!(r > 0.0) || !std::isfinite(r)) throw InputError(fmt::format("particle radius {} is not positive", r));
  }
  rebuild();
}

void ContactSystem::rebuild() {
  const auto order = neighbours_.spatial_order(box_, particles_.position, particles_.max_radius());
  particles_.permute(order);
  neighbours_.build(box_, particles_.position, particles_.radius);
  nonaffine_.assign(size(), Vec3::Zero());
  max_nonaffine_ = 0.0;
}

bool ContactSystem::ensure_neighbours(double extra_nonaffine, double strain) {
  if (neighbours_.valid_for(max_nonaffine_ + extra_nonaffine, strain)) return false;
  rebuild();
  return true;
}

const ContactField& ContactSystem::compute_forces(const ForceRequest& request) {
  compute_contact_forces(*law_, box_, particles_.position, particles_.radius, neighbours_, request,
                         field_);
  return field_;
}

void ContactSystem::set_strain(double strain) {
  box_.set_strain(strain);
  rebuild();
}

void ContactSystem::rescale(double factor) {
  for (auto& x : particles_.position) x *= factor;
  const double strain = box_.strain();
  box_ = LeesEdwardsBox(box_.side() * factor);
  box_.set_strain(strain);
  for (auto& x : particles_.position) box_.wrap(x);
  rebuild();
}

void ContactSystem::restore_tracking(Tracking t) {
  nonaffine_ = std::move(t.nonaffine);
  max_nonaffine_ = t.max_nonaffine;
}

void ContactSystem::restore_positions(const std::vector<Vec3>& x, double strain) {
  particles_.position = x;
  box_.set_strain(strain);
}

std::size_t ContactSystem::memory_bytes() const {
  return size() * (2 * sizeof(Vec3) + sizeof(double) + sizeof(std::uint32_t)) +
         nonaffine_.capacity() * sizeof(Vec3) + neighbours_.memory_bytes() + field_.memory_bytes();
}

}  // namespace softglass::micro
