// The linear shear modulus G0 of a relaxed packing (spec §6.4), exactly, from the
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
#pragma once

#include <cstddef>

#include "micro/system/contact_system.h"

namespace softglass::micro {

struct ShearModulus {
  double modulus = 0.0;         // G0, units of E*
  double affine_modulus = 0.0;  // E_γγ / V, the upper bound without relaxation
  std::size_t iterations = 0;   // conjugate-gradient iterations
  double solver_error = 0.0;    // relative residual of H u = Ξ
};

ShearModulus shear_modulus(ContactSystem& system, double tolerance = 1e-10);

}  // namespace softglass::micro
