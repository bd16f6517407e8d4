// Particles in a Lees–Edwards cell interacting through a contact law: the state
// that every algorithm (minimisation, sheared dynamics, linear response) moves
// and evaluates.
//
// It owns the neighbour list and keeps it valid: integrators announce how far
// they are about to move (`ensure_neighbours`), move particles through `move`,
// which records the non-affine part of each displacement, and the
// list is rebuilt — with the particles reordered cell by cell for locality —
// only when the bound of neighbour_list.h says a contact could be missed.
//
// The forces loop over a narrower list filtered from it (neighbour_list.h):
// the pairs within a quarter of the skin, refreshed in one pass over the wide
// list when a move would leave it. With the usual skin of 0.6 R a fifth of the
// wide list's pairs drop out, and the pass that finds the touching pairs was
// half of the contact kernel (docs/validation.md). The narrow list serves an
// evaluation only when its own bound holds at that moment, else the wide list
// does, so callers see the wide list's validity alone and the forces are the
// same bits either way.
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
  /// The list the next evaluation loops over: the narrow one while its bound
  /// holds at the current configuration, else the wide one.
  const NeighbourList& contact_list() const {
    return near_.valid_for(max_near_nonaffine_, box_.strain()) ? near_ : neighbours_;
  }

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
    std::vector<Vec3> nonaffine, near_nonaffine;  // since the build, the filtering
    double max_nonaffine, max_near_nonaffine;
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
  void refilter();
  // Positions x = x⁰ + increment y⁰ e_x + dt v and the trackings u = u⁰ + dt v,
  // w = w⁰ + dt v, from arrays x⁰, u⁰, w⁰ that may be the system's own.
  void move_from(double increment, double dt, std::span<const Vec3> v, const Vec3* x0,
                 const Vec3* u0, const Vec3* w0);
  // Every change of the positions, the cell or the particles' order counts
  // one configuration; the field remembers the one it was computed at.
  void changed() { ++configuration_; }

  Particles particles_;
  LeesEdwardsBox box_;
  std::shared_ptr<const ContactLaw> law_;
  Walls walls_;
  NeighbourList neighbours_;
  // The narrow list and its share of the skin. A quarter: at φ = 0.80 the pairs
  // per particle are 6.54, 5.63, 5.22 and 5.00 for skins 0.6, 0.3, 0.15 and
  // 0.08 R, and a narrower list is refreshed more often for little gain.
  static constexpr double kNearSkinFraction = 0.25;
  NeighbourList near_;
  ContactField field_;
  std::uint64_t configuration_ = 0;
  std::uint64_t field_configuration_ = ~std::uint64_t{0};  // none yet
  ForceRequest field_request_{};
  std::vector<Vec3> nonaffine_;  // since the last build
  double max_nonaffine_ = 0.0;
  std::vector<Vec3> near_nonaffine_;  // since the last filtering
  double max_near_nonaffine_ = 0.0;
};

}  // namespace softglass::micro
