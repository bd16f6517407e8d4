// The linear shear modulus G0 of a relaxed packing (docs/physics.md, "Protocol"), exactly, from the
// Hessian rather than by finite strains.
//
// Under a small affine shear γ (x → x + γ y e_x, Lees–Edwards offset γL) followed
// by relaxation, the energy of a force-balanced packing changes as
//     E(γ) = E(0) + V σ_xy γ + ½ V G γ²,   G = (E_γγ − Ξᵀ H⁺ Ξ) / V,
// with H the Hessian of the energy in the positions, E_γγ the second derivative
// along the affine path, and Ξ = ∂²E/∂x∂γ the forces the affine shear creates
// (Maloney & Lemaître, PRE 74, 016118 (2006)). For a pair with separation d, the
// affine path moves d by γ d_y e_x, so with r_γ = d_x d_y / r:
//     E_γγ  += k r_γ² − f d_y² (1 − n_x²)/r
//     Ξ_i   += k r_γ n − f d_y (e_x − n n_x)/r      (Ξ_j −= the same)
//     H_ij  block K = k nn − (f/r)(I − nn)
// where f is the repulsive force magnitude and k = df/dh the normal stiffness.
// H⁺Ξ is found by conjugate gradients (Eigen); H is singular only along rigid
// translations and rattlers, to which Ξ is orthogonal.
//
// Which shear. The same formula holds for the simple shear of any pair of axes
// (flow a, gradient b: d → d + γ d_b e_a). A finite packing is not isotropic:
// at N = 250, φ = 0.85 the x–y modulus alone ranges over a factor of 5 between
// packings of identical Z and pressure (docs/physics.md), because it reads one
// direction's softest relaxation modes. G0 is therefore the mean over the six
// simple shears (a ≠ b), the isotropic modulus a macroscopic sample shows; the
// x–y value (the Lees–Edwards shear) is kept beside it.
#pragma once

#include <array>
#include <string>
#include <cstddef>

#include "micro/model/contact_system.h"

namespace softglass::micro {

/// The six simple shears (flow axis, gradient axis), x–y first.
inline constexpr std::array<std::array<int, 2>, 6> kSimpleShears = {
    {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}}};

struct ShearModulus {
  double modulus = 0.0;                // G0: mean over the six simple shears, units of E*
  double flow_gradient_modulus = 0.0;  // the x–y simple shear alone (directions[0])
  double direction_spread = 0.0;       // standard deviation over the six
  double affine_modulus = 0.0;         // mean E_γγ / V, the upper bound without relaxation
  std::array<double, 6> directions{};  // each simple shear's modulus, in kSimpleShears order
  std::array<double, 6> affine_directions{};
  std::size_t iterations = 0;  // conjugate-gradient iterations, all six solves
  double solver_error = 0.0;   // largest relative residual of H u = Ξ
};

ShearModulus shear_modulus(ContactSystem& system, double tolerance = 1e-10);

/// A packing is a solid only if its modulus is positive and stands above the
/// scatter of its six simple shears; otherwise it is not at a stable minimum (or
/// too small to be isotropic) and every flow curve sheared from it would be
/// that of another material. NumericalError naming `packing` (its φ and seed)
/// and the figures, so that a campaign stops at the packing instead of at its
/// last step.
void require_solid(const ShearModulus& modulus, const std::string& packing);

}  // namespace softglass::micro
