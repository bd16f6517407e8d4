// The square duct (Mosolov problem): when does a Bingham material flow at all?
//
// Along a duct of cross-section S driven by G = −dp/dz, the axial velocity w
// minimises ∫_S [φ(|∇w|) − G w], φ(γ̇) = τ_y γ̇ + K γ̇^{n+1}/(n+1) the
// dissipation potential (γ̇ = |∇w| in the conventions of docs/macro.md). Testing
// the functional with small multiples of (smoothed) indicators of subsets
// A ⊂ S, and the coarea formula for the converse, show that w ≡ 0 is the
// minimiser exactly when τ_y |∂A| ≥ G |A| for every A (Mosolov & Miasnikov
// 1965): the flow stops at τ_y,c = G max_A |A|/|∂A| = G/h(S), h(S) the Cheeger
// constant of S. For a square of side a the Cheeger set is the square with its
// corners rounded to radius 1/h, and h = (2 + √π)/a (Kawohl & Lachand-Robert
// 2006), so
//
//     τ_y,c = G a/(2 + √π).
//
// In terms of the mean wall stress τ_w = G|S|/|∂S| = G a/4 this is
// Bi_c = τ_y,c/τ_w = 4/(2 + √π) ≈ 1.0603, the number macro.md quotes for
// Rheolef's scaling. (Rheolef's velocity scale, needed for its u_max, is not
// checked here.) The result holds for any n: the criterion involves only the
// yield term.
#pragma once

#include <cmath>
#include <numbers>

namespace softglass::macro::exact {

/// τ_y,c = G a/(2 + √π) [Pa]: no flow for τ_y ≥ τ_y,c in a square duct of side
/// a [m] under G = −dp/dz [Pa/m].
inline double square_duct_critical_yield_stress(double side, double pressure_gradient) {
  return pressure_gradient * side / (2.0 + std::sqrt(std::numbers::pi));
}

}  // namespace softglass::macro::exact
