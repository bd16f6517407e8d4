// The solvent's friction on a particle's own motion, and what that motion is
// measured against.
//
// The paper (and `affine`, the default): u_α − u∞(x_α) = M_α F_α, i.e. a
// friction ζ_α = 6π γ̃ R_α / f_r against the imposed affine flow, as if every
// particle moved through a solvent that itself flows affinely (Durian's
// "mean-field" drag). In a paste the solvent is held in the films between the
// particles and moves with them; `neighbours` makes the friction act on the
// motion relative to the neighbours instead (Durian's original bubble model),
// as pair dashpots on the relative velocity u_α − u_β of each contact:
//     b_c = (1 − κ) ½ (ζ_α/z_α + ζ_β/z_β),
// so that a particle moving past neighbours at rest feels about ζ_α in all,
// while a uniform or rigid collective motion feels none. A share κ of the
// friction stays against the affine flow: it keeps a particle without contacts
// (a rattler) moving with the solvent and the velocities unique.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "micro/contact/contact_forces.h"

namespace softglass::micro {

enum class StokesReference { affine, neighbours };
StokesReference parse_stokes_reference(const std::string& name);
std::string to_string(StokesReference reference);
/// "affine|neighbours", for the parameter file.
std::string stokes_reference_names();

struct StokesFriction {
  StokesReference reference = StokesReference::affine;
  double reservoir_share = 0.01;  // κ, for `neighbours`

  /// The friction against the affine flow of a particle with Stokes friction ζ.
  double reservoir(double zeta) const {
    return reference == StokesReference::affine ? zeta : reservoir_share * zeta;
  }
  /// b_c for every contact of `contacts` (all 0 for `affine`), from the
  /// particles' Stokes frictions ζ.
  void pair_coefficients(const ContactList& contacts, std::span<const double> zeta,
                         std::vector<double>& out) const;
  bool has_pairs() const { return reference == StokesReference::neighbours; }
};

}  // namespace softglass::micro
