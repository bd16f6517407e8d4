#include "micro/model/contact_system.h"

#include <omp.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "micro/numerics/thread_range.h"
#include "micro/numerics/vector_clones.h"

namespace softglass::micro {

ContactSystem::ContactSystem(Particles particles, LeesEdwardsBox box,
                             std::shared_ptr<const ContactLaw> law, double skin)
    : particles_(std::move(particles)), box_(box), law_(std::move(law)), neighbours_(skin),
      near_(kNearSkinFraction * skin) {
  for (auto& x : particles_.position) {
    if (!x.allFinite()) throw InputError("a particle position is not finite");
    box_.wrap(x);
  }
  for (double r : particles_.radius) {
    if (!(r > 0.0) || !std::isfinite(r))
      throw InputError(fmt::format("particle radius {} is not positive", r));
  }
  rebuild();
}

namespace {
struct Maxima {
  double wide = 0.0, near = 0.0;  // largest |u|², |w|²
};
// Particles [first, last): x = x⁰ + increment y⁰ e_x + dt v and the tracked
// non-affine displacements u = u⁰ + dt v (since the build) and w = w⁰ + dt v
// (since the filtering), from the arrays x⁰, u⁰, w⁰ (which may be x, u, w
// themselves); returns their largest squares.
SOFTGLASS_VECTOR_CLONES Maxima move_range(double increment, double dt, const Vec3* v,
                                          const Vec3* x0, const Vec3* u0, const Vec3* w0,
                                          Vec3* x, Vec3* u, Vec3* w, std::size_t first,
                                          std::size_t last) {
  double wide = 0.0, near = 0.0;
#pragma omp simd reduction(max : wide, near)
  for (std::size_t i = first; i < last; ++i) {
    // Componentwise, and in the order of shear() then move(): x += Δγ y, then
    // x += dt v.
    const Vec3 step = dt * v[i];
    x[i] = Vec3(x0[i].x() + increment * x0[i].y() + step.x(), x0[i].y() + step.y(),
                x0[i].z() + step.z());
    u[i] = u0[i] + step;
    w[i] = w0[i] + step;
    wide = std::max(wide, u[i].squaredNorm());
    near = std::max(near, w[i].squaredNorm());
  }
  return {wide, near};
}
}  // namespace

void ContactSystem::move(double dt, std::span<const Vec3> v) {
  move_from(0.0, dt, v, particles_.position.data(), nonaffine_.data(), near_nonaffine_.data());
}

void ContactSystem::shear_and_move(double increment, double dt, std::span<const Vec3> v,
                                   std::vector<Vec3>& position_before, Tracking& before) {
  const std::size_t n = size();
  position_before.resize(n);
  before.nonaffine.resize(n);
  before.near_nonaffine.resize(n);
  std::swap(particles_.position, position_before);
  std::swap(nonaffine_, before.nonaffine);
  std::swap(near_nonaffine_, before.near_nonaffine);
  before.max_nonaffine = max_nonaffine_;
  before.max_near_nonaffine = max_near_nonaffine_;
  move_from(increment, dt, v, position_before.data(), before.nonaffine.data(),
            before.near_nonaffine.data());
  box_.advance_strain(increment);
}

void ContactSystem::move_from(double increment, double dt, std::span<const Vec3> v,
                              const Vec3* x0, const Vec3* u0, const Vec3* w0) {
  changed();
  const std::size_t n = size();
  Vec3* x = particles_.position.data();
  Maxima m{max_nonaffine_ * max_nonaffine_, max_near_nonaffine_ * max_near_nonaffine_};
  const auto range = [&](std::size_t first, std::size_t last) {
    return move_range(increment, dt, v.data(), x0, u0, w0, x, nonaffine_.data(),
                      near_nonaffine_.data(), first, last);
  };
  // One thread moves them all without entering a parallel region: even one
  // whose `if` turns it off is a libgomp call per step.
  const int threads = n >= 4096 ? omp_get_max_threads() : 1;
  if (threads == 1) {
    const Maxima r = range(0, n);
    m = {std::max(m.wide, r.wide), std::max(m.near, r.near)};
  } else {
    double wide = m.wide, near = m.near;
#pragma omp parallel num_threads(threads) reduction(max : wide, near)
    {
      const auto [first, last] = thread_range(n, threads, omp_get_thread_num());
      const Maxima r = range(first, last);
      wide = std::max(wide, r.wide);
      near = std::max(near, r.near);
    }
    m = {wide, near};
  }
  max_nonaffine_ = std::sqrt(m.wide);
  max_near_nonaffine_ = std::sqrt(m.near);
}

void ContactSystem::shear(double increment) {
  changed();
  for (Vec3& x : particles_.position) x.x() += increment * x.y();
  box_.advance_strain(increment);
}

void ContactSystem::rebuild() {
  changed();
  for (auto& x : particles_.position) box_.wrap(x);
  const auto order = neighbours_.spatial_order(box_, particles_.position, particles_.max_radius());
  particles_.permute(order);
  neighbours_.build(box_, particles_.position, particles_.radius);
  nonaffine_.assign(size(), Vec3::Zero());
  max_nonaffine_ = 0.0;
  refilter();
}

void ContactSystem::refilter() {
  near_.filter(neighbours_, box_, particles_.position);
  near_nonaffine_.assign(size(), Vec3::Zero());
  max_near_nonaffine_ = 0.0;
}

bool ContactSystem::ensure_neighbours(double extra_nonaffine, double strain) {
  if (!neighbours_.valid_for(max_nonaffine_ + extra_nonaffine, strain)) {
    rebuild();
    return true;
  }
  // The narrow list is refreshed if the move would leave it, unless even a
  // fresh one would not hold (a wide margin of the implicit step): the wide
  // list serves those evaluations.
  if (!near_.valid_for(max_near_nonaffine_ + extra_nonaffine, strain) &&
      near_.reach_after(std::abs(strain - box_.strain())) > extra_nonaffine)
    refilter();
  return false;
}

const ContactField& ContactSystem::compute_forces(const ForceRequest& request) {
  compute_contact_forces(*law_, box_, particles_.position, contact_list(), request, field_);
  if (walls_.present())
    add_wall_forces(*law_, walls_, particles_.position, particles_.radius, request, field_);
  field_configuration_ = configuration_;
  field_request_ = request;
  return field_;
}

const ContactField& ContactSystem::current_forces(const ForceRequest& request) {
  const ForceRequest& had = field_request_;
  const bool covered = (had.energy || !request.energy) && (had.contacts || !request.contacts) &&
                       (had.virial || !request.virial);
  if (field_configuration_ == configuration_ && covered) return field_;
  return compute_forces(request);
}

void ContactSystem::set_walls(const Walls& walls) {
  walls.check_inside(box_.side(), particles_.max_radius(), neighbours_.skin());
  walls_ = walls;
  changed();
}

double ContactSystem::occupied_volume_fraction() const {
  if (!walls_.present()) return volume_fraction();
  return particles_.total_volume() / (box_.side() * box_.side() * walls_.gap());
}

Particles ContactSystem::wrapped_in_label_order() const {
  Particles p = particles_.in_label_order();
  for (auto& x : p.position) box_.wrap(x);
  return p;
}

void ContactSystem::set_strain(double strain) {
  box_.set_strain(strain);  // rebuild() counts the change
  rebuild();
}

void ContactSystem::rescale(double factor) {
  // rebuild(), at the end, counts the change.
  for (auto& x : particles_.position) x *= factor;
  const double strain = box_.strain();
  box_ = LeesEdwardsBox(box_.side() * factor);
  walls_ = {walls_.lower * factor, walls_.upper * factor};
  box_.set_strain(strain);
  for (auto& x : particles_.position) box_.wrap(x);
  rebuild();
}

void ContactSystem::save_tracking(Tracking& into) const {
  into.nonaffine.assign(nonaffine_.begin(), nonaffine_.end());
  into.near_nonaffine.assign(near_nonaffine_.begin(), near_nonaffine_.end());
  into.max_nonaffine = max_nonaffine_;
  into.max_near_nonaffine = max_near_nonaffine_;
}

void ContactSystem::restore_tracking(const Tracking& from) {
  nonaffine_.assign(from.nonaffine.begin(), from.nonaffine.end());
  near_nonaffine_.assign(from.near_nonaffine.begin(), from.near_nonaffine.end());
  max_nonaffine_ = from.max_nonaffine;
  max_near_nonaffine_ = from.max_near_nonaffine;
}

void ContactSystem::restore_positions(const std::vector<Vec3>& x, double strain) {
  changed();
  particles_.position.assign(x.begin(), x.end());
  box_.set_strain(strain);
}

std::size_t ContactSystem::memory_bytes() const {
  return size() * (2 * sizeof(Vec3) + sizeof(double) + sizeof(std::uint32_t)) +
         (nonaffine_.capacity() + near_nonaffine_.capacity()) * sizeof(Vec3) +
         neighbours_.memory_bytes() + near_.memory_bytes() + field_.memory_bytes();
}

}  // namespace softglass::micro
