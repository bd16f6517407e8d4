// What a wall run measures at one instant: the stress each smooth wall
// carries, the bulk stress and shear rate in the middle of the gap, the slip,
// and the velocity profile across the gap (docs/physics.md, "Wall slip").
//
// Wall stress. A flat wall's elastic force is normal (contact/wall_contacts.h),
// so a smooth wall takes shear only through its films: with f_k the film drag
// on the particle of wall contact k (model/wall_films.h) and A = L² the wall
// area, the lower wall is pulled along +x by σ_w,lo = −Σ_lo f_k,x / A and the
// upper one held back by σ_w,hi = +Σ_hi f_k,x / A (both positive for c > 0).
//
// Bulk stress: the Irving–Kirkwood virial of the pair forces (elastic, film,
// Stokes pair dashpots) in the central slab y_a < y < y_b, each pair weighted
// by the share of its segment d inside the slab:
//     σ_yx = −(1/(A (y_b − y_a))) Σ_c d_y^{in} f_x .
// It equals the mean over planes y₀ ∈ (y_a, y_b) of the force per area that
// the particles above y₀ exert on those below (method of planes).
//
// Force balance. Every particle is force-free at every instant (overdamped
// motion), so the particles below a plane y₀ balance: the lower wall's drag,
// the force across the plane, and the one-body Stokes friction
// −ζ_r (v_α,x − v̄(y_α)) against the solvent (the reservoir share,
// model/stokes_friction.h; v̄ the solvent's non-affine velocity,
// model/solvent_flow.h):
//     σ_yx(y₀) = σ_w,lo + (1/A) Σ_{y_α<y₀} ζ_r (v_α,x − v̄(y_α)) .
// Averaged over the central planes, the sum weights particle α by the share
// of (y_a, y_b) above it (`reservoir_term`). This holds at every sample, to the
// velocity solve's tolerance. The bulk stress differs from σ_w by it, and the
// upper wall's stress from the lower's by the sum over all particles: against
// the local mean flow both are the fluctuations' (zero on average up to the
// profile's lag); against the affine flow they are a body force on the plug.
//
// Bulk rate and slip. u_x = c y_α + v_α,x fitted linearly in y_α over the
// particles in the central slab gives γ̇_bulk (units of the reference rate);
// the walls move at c y_w, so V_top − V_bottom = c H and the slip velocity
// of each wall is V_s = (c − γ̇_bulk) H / 2 (units γ̇ R).
#pragma once

#include <vector>

#include "micro/model/overdamped_shear.h"

namespace softglass::micro {

struct WallSampleSettings {
  double central_fraction = 0.5;  // the central slab's share of the gap
  std::size_t bins = 20;          // velocity-profile bins across the gap

  void validate() const;
};

struct WallSample {
  double wall_stress_lower = 0.0, wall_stress_upper = 0.0;    // σ_w, units E*
  double normal_stress_lower = 0.0, normal_stress_upper = 0.0;  // Σ|f|/A of the wall contacts
  double contacts_lower = 0.0, contacts_upper = 0.0;          // wall contacts per area (R⁻²)
  double bulk_stress = 0.0, bulk_stress_elastic = 0.0;        // central σ_yx and its elastic part
  double reservoir_term = 0.0;  // the reservoir friction's share (see the header)
  double reservoir_total = 0.0;  // (1/A) Σ_α ζ_r v_α,x: σ_w,hi − σ_w,lo by force balance
  double bulk_rate = 0.0;       // γ̇_bulk / γ̇_ref
  double slip_velocity = 0.0;   // V_s, units γ̇_ref R
  std::vector<double> profile;  // mean u_x per bin (units γ̇_ref R); NaN for an empty bin
  std::vector<double> profile_count;  // particles per bin
};

/// The sample of `flow` at its last evaluation (which must have computed the
/// contacts: flows with the EHD drag or the Stokes pair dashpots do).
WallSample measure_wall_sample(const OverdampedShear& flow, const WallSampleSettings& settings);

}  // namespace softglass::micro
