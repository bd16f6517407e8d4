// Particles in a Lees–Edwards cell interacting through a contact law: the state
// that every algorithm (minimisation, sheared dynamics, linear response) moves
// and evaluates.
//
// It owns the neighbour list and keeps it valid: integrators announce how far
// they are about to move (`ensure_neighbours`), move particles through
// `move_all`, which records the non-affine part of each displacement, and the
// list is rebuilt — with the particles reordered cell by cell for locality —
// only when the bound of neighbour_list.h says a contact could be missed.
#pragma once

#include <algorithm>
#include <memory>

#include "micro/contact/contact_law.h"
#include "micro/forces/contact_forces.h"
#include "micro/neighbour/neighbour_list.h"
#include "micro/system/particles.h"

namespace softglass::micro {

class ContactSystem {
 public:
  ContactSystem(Particles particles, LeesEdwardsBox box, std::shared_ptr<const ContactLaw> law,
                double skin);

  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }
  const LeesEdwardsBox& box() const { return box_; }
  const ContactLaw& law() const { return *law_; }
  std::shared_ptr<const ContactLaw> shared_law() const { return law_; }
  std::size_t size() const { return particles_.size(); }
  double volume_fraction() const { return particles_.total_volume() / box_.volume(); }
  const NeighbourList& neighbours() const { return neighbours_; }

  /// Elastic forces at the current configuration (the list must be valid).
  const ContactField& compute_forces(const ForceRequest& request = {});
  const ContactField& forces() const { return field_; }

  /// Rebuilds the list (reordering particles) unless it stays valid for a further
  /// non-affine move of up to `extra_nonaffine` per particle and strain `strain`.
  /// Returns true when it rebuilt; per-particle arrays held outside must then be
  /// re-read (they are permuted with `particles()`).
  bool ensure_neighbours(double extra_nonaffine, double strain);
  bool ensure_neighbours(double extra_nonaffine = 0.0) {
    return ensure_neighbours(extra_nonaffine, box_.strain());
  }

  /// Moves every particle: `step(i)` returns {displacement, its non-affine part}.
  /// Positions are wrapped into the cell; the caller advances the strain.
  template <class Step>
  void move_all(Step&& step);

  void advance_strain(double increment) { box_.advance_strain(increment); }
  void set_strain(double strain);
  /// Scales positions and cell by `factor` (compression when < 1).
  void rescale(double factor);

  double max_nonaffine_displacement() const { return max_nonaffine_; }

  /// Non-affine displacement bookkeeping, exposed so that an integrator can save
  /// and restore it along with the positions when it rejects a step.
  struct Tracking {
    std::vector<Vec3> nonaffine;
    double max_nonaffine;
  };
  Tracking tracking() const { return {nonaffine_, max_nonaffine_}; }
  void restore_tracking(Tracking t);
  void restore_positions(const std::vector<Vec3>& x, double strain);

  std::size_t memory_bytes() const;

 private:
  void rebuild();

  Particles particles_;
  LeesEdwardsBox box_;
  std::shared_ptr<const ContactLaw> law_;
  NeighbourList neighbours_;
  ContactField field_;
  std::vector<Vec3> nonaffine_;  // since the last build
  double max_nonaffine_ = 0.0;
};

template <class Step>
void ContactSystem::move_all(Step&& step) {
  const std::size_t n = size();
  double max2 = max_nonaffine_ * max_nonaffine_;
#pragma omp parallel for schedule(static) reduction(max : max2) if (n >= 4096)
  for (std::size_t i = 0; i < n; ++i) {
    const auto [displacement, nonaffine] = step(i);
    particles_.position[i] += displacement;
    box_.wrap(particles_.position[i]);
    nonaffine_[i] += nonaffine;
    max2 = std::max(max2, nonaffine_[i].squaredNorm());
  }
  max_nonaffine_ = std::sqrt(max2);
}

}  // namespace softglass::micro
