// Particles in a Lees–Edwards cell interacting through a contact law: the state
// that every algorithm (minimisation, sheared dynamics, linear response) moves
// and evaluates.
//
// It owns the neighbour list and keeps it valid: integrators announce how far
// they are about to move (`ensure_neighbours`), move particles through `move`,
// which records the non-affine part of each displacement, and the
// list is rebuilt — with the particles reordered cell by cell for locality —
// only when the bound of neighbour_list.h says a contact could be missed.
#pragma once

#include <memory>
#include <span>

#include "micro/contact/contact_forces.h"
#include "micro/contact/contact_law.h"
#include "micro/geometry/neighbour_list.h"
#include "micro/geometry/particles.h"

namespace softglass::micro {

class ContactSystem {
 public:
  ContactSystem(Particles particles, LeesEdwardsBox box, std::shared_ptr<const ContactLaw> law,
                double skin);

  /// Particles in the engine's order, positions not necessarily in the cell.
  /// Positions change only through the methods below (move, shear, …), which
  /// is what lets current_forces tell a configuration it has evaluated.
  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }
  /// Particles in label order with positions wrapped into the cell: for output.
  Particles wrapped_in_label_order() const;
  const LeesEdwardsBox& box() const { return box_; }
  const ContactLaw& law() const { return *law_; }
  std::shared_ptr<const ContactLaw> shared_law() const { return law_; }
  std::size_t size() const { return particles_.size(); }
  double volume_fraction() const { return particles_.total_volume() / box_.volume(); }
  const NeighbourList& neighbours() const { return neighbours_; }

  /// Smooth walls (wall_contacts.h); none by default. Checked against the
  /// cell, the largest radius and the skin (InputError).
  void set_walls(const Walls& walls);
  const Walls& walls() const { return walls_; }
  /// φ of the particles in the volume they can occupy: the slab L²(y_hi − y_lo)
  /// between the walls, or the cell.
  double occupied_volume_fraction() const;

  /// Elastic forces at the current configuration (the list must be valid).
  const ContactField& compute_forces(const ForceRequest& request = {});
  const ContactField& forces() const { return field_; }
  /// The same, but the last evaluation's if nothing has moved, been reordered
  /// or sheared since and it computed at least what `request` asks for: the
  /// implicit step freezes its drag at the point its last solve evaluated.
  const ContactField& current_forces(const ForceRequest& request);

  /// Rebuilds the list (reordering particles) unless it stays valid for a further
  /// non-affine move of up to `extra_nonaffine` per particle and strain `strain`.
  /// Returns true when it rebuilt; per-particle arrays held outside must then be
  /// re-read (they are permuted with `particles()`).
  bool ensure_neighbours(double extra_nonaffine, double strain);
  bool ensure_neighbours(double extra_nonaffine = 0.0) {
    return ensure_neighbours(extra_nonaffine, box_.strain());
  }

  /// Moves every particle by dt v_i, the non-affine displacement the list
  /// tracks. Positions move continuously (they are wrapped into the cell when
  /// the list is rebuilt).
  void move(double dt, std::span<const Vec3> v);
  /// Shears the cell and the particles affinely by `increment` of strain
  /// (x_i += increment · y_i e_x; either sign).
  void shear(double increment);
  void set_strain(double strain);
  /// Scales positions, cell and walls by `factor` (compression when < 1).
  void rescale(double factor);

  double max_nonaffine_displacement() const { return max_nonaffine_; }

  /// Non-affine displacement bookkeeping, exposed so that an integrator can save
  /// and restore it along with the positions when it rejects a step.
  struct Tracking {
    std::vector<Vec3> nonaffine;
    double max_nonaffine;
  };
  void save_tracking(Tracking& into) const;
  void restore_tracking(const Tracking& from);
  void restore_positions(const std::vector<Vec3>& x, double strain);
  /// shear(increment) then move(dt, v), in one pass; the positions and the
  /// tracking they leave are handed to `position_before` and `before` (to
  /// restore a rejected step) by swapping arrays, not copying them.
  void shear_and_move(double increment, double dt, std::span<const Vec3> v,
                      std::vector<Vec3>& position_before, Tracking& before);

  std::size_t memory_bytes() const;

 private:
  void rebuild();
  // Positions x = x⁰ + increment y⁰ e_x + dt v and the tracking u = u⁰ + dt v,
  // from arrays x⁰, u⁰ that may be the system's own.
  void move_from(double increment, double dt, std::span<const Vec3> v, const Vec3* x0,
                 const Vec3* u0);
  // Every change of the positions, the cell or the particles' order counts
  // one configuration; the field remembers the one it was computed at.
  void changed() { ++configuration_; }

  Particles particles_;
  LeesEdwardsBox box_;
  std::shared_ptr<const ContactLaw> law_;
  Walls walls_;
  NeighbourList neighbours_;
  ContactField field_;
  std::uint64_t configuration_ = 0;
  std::uint64_t field_configuration_ = ~std::uint64_t{0};  // none yet
  ForceRequest field_request_{};
  std::vector<Vec3> nonaffine_;  // since the last build
  double max_nonaffine_ = 0.0;
};

}  // namespace softglass::micro
