// Packings between two smooth walls (contact/wall_contacts.h): the particles
// of a packing spec compressed in a cell whose slab y_lo < y < y_hi they
// fill at volume fraction φ = Σ (4/3)π R_α³ / (L² (y_hi − y_lo)).
//
// Geometry. The cell stays cubic (Lees–Edwards box): with the slab
// s = 2(R_max + skin) left empty across the periodic y boundary, the side L
// solves φ L² (L − s) = Σ (4/3)π R_α³, and the walls sit at y_lo = s/2 and
// y_hi = L − s/2, a gap H = L − s. The particle number and φ thus set the gap
// (H ≈ (N v̄/φ)^{1/3} − s … a few R short of the cube's side).
//
// Protocol: that of make_packing (packing.h) with the walls in the energy —
// centres uniform in the slab at φ₀, compression stage by stage (the walls
// move with the cell), FIRE relaxation to force balance at φ.
#pragma once

#include <functional>
#include <memory>

#include "micro/contact/wall_contacts.h"
#include "micro/packing/packing.h"

namespace softglass::micro {

/// The narrowest gap accepted, in units of R: two particle diameters, below
/// which no particle layer is away from both walls.
inline constexpr double kMinWallGap = 4.0;

struct WallPacking {
  Packing packing;
  Walls walls;
};

/// The packing of `spec` between walls. InputError if the gap it implies is
/// below kMinWallGap.
WallPacking make_wall_packing(const PackingSpec& spec, std::shared_ptr<const ContactLaw> law,
                              const std::function<void(double)>& progress = {});

/// The side L of the cubic cell holding particles of total volume `volume` at
/// φ in the slab between walls, with `slab` left empty: φ L² (L − slab) = volume.
double wall_cell_side(double volume, double volume_fraction, double slab);

}  // namespace softglass::micro
