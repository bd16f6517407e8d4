// The solvent's velocity, against which the reservoir share of the Stokes
// friction acts (stokes_friction.h).
//
// In homogeneous shear the solvent flows with the imposed affine flow
// u∞ = c y e_x, and the reservoir friction is −ζ_r (u_α − u∞(x_α)) = −ζ_r v_α
// (`affine`, the paper's choice). Between smooth walls the suspension's mean
// flow is not affine: below the yield stress it moves as a plug and slips on
// both walls, and even above it the profile bends near the walls. A friction
// against the affine flow would then drag every particle of the plug towards
// the velocity the affine flow has at its height — a body force of the order
// of the wall stress itself (ζ_r |v| ~ ζ_r γ̇ H/2 per particle), which is not in
// the physics: in a paste the solvent sits in the films between the particles
// and is carried along with them. `local mean` therefore measures the
// reservoir friction against the mean velocity of the suspension at the
// particle's height,
//     −ζ_r (u_α − ū(y_α)),   ū(y) = c y + v̄(y) e_x,
// with ū the mean x-velocity of the particles on nodes about one radius apart
// across the gap, linear between them (constant beyond the outer ones), and
// v̄(y) = ū(y) − c y its non-affine part. Particles are deposited on the nodes
// and ū read back with the same linear ("cloud-in-cell") weights W_k(y),
// Σ_k W_k = 1, each deposit weighted by the particle's reservoir friction ζ_α:
//     ū_k = Σ_α W_k(y_α) ζ_α u_α,x / Σ_α W_k(y_α) ζ_α,   ū(y) = Σ_k W_k(y) ū_k.
// Two exact properties follow. Σ_α ζ_α ū(y_α) = Σ_α ζ_α u_α,x: the friction
// against the local mean flow exerts no net force on the particles (the
// solvent carried with them exchanges no momentum with them on the whole),
// whatever the profile. And a plug, u_α,x = U for all α, is its own mean flow
// however the particles are layered between the nodes (which is why the total
// velocity u, constant in a plug, is deposited rather than v, linear in y
// there): no particle of a plug feels the reservoir friction. In homogeneous
// shear v̄ ≈ 0 and the two choices coincide on average.
//
// v̄ is lagged: each evaluation solves the velocities against the profile of
// the previous one (during a solve the reference is a fixed field, so the
// velocity solve keeps its convex form and unique solution; a self-consistent
// mean would leave a uniform translation of a slab without friction). The lag
// is one time step, over which the profile changes by O(dt) of itself; the
// net force is then the rate of change of the ζ-weighted mean velocity, zero
// in a steady state.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

enum class SolventReference { affine, local_mean };
SolventReference parse_solvent_reference(const std::string& name);
std::string to_string(SolventReference reference);
/// "affine|local mean", for the parameter file.
std::string solvent_reference_names();

class SolventFlow {
 public:
  /// The affine flow: v̄ ≡ 0.
  SolventFlow() = default;
  /// The local mean flow between heights `lower` and `upper`, on nodes about
  /// `spacing` apart (units R; at least two). InputError if not upper > lower.
  static SolventFlow local_mean(double lower, double upper, double spacing = 1.0);

  bool affine() const { return profile_.empty(); }
  /// v̄(y) = ū(y) − c y: the solvent's non-affine x-velocity at height y
  /// under the affine flow of rate c (0 if affine; c y e_x, i.e. v̄ = 0,
  /// before the first update).
  double velocity(double y, double rate) const;
  /// Re-estimates ū from the particles' positions, non-affine velocities and
  /// reservoir frictions at rate c (a node without particles keeps its last
  /// value).
  void update(std::span<const Vec3> x, std::span<const Vec3> v, std::span<const double> friction,
              double rate);

  /// ū per node.
  const std::vector<double>& profile() const { return profile_; }

 private:
  /// The node k below y and the weight 1 − s of k (s of k + 1), with the
  /// ends clamped: W_k(y) = 1 − s, W_{k+1}(y) = s.
  struct Weights {
    std::size_t k;
    double s;
  };
  Weights weights(double y) const;

  double lower_ = 0.0, spacing_ = 0.0;  // height of the first node, node spacing
  std::vector<double> profile_;         // ū_k
  bool filled_ = false;                 // updated at least once
  std::vector<double> sum_, weight_;    // update's scratch
};

}  // namespace softglass::micro
