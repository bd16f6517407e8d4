// Poiseuille flow in a circular pipe: the exact solution for a Herschel–Bulkley
// material and, by quadrature, for its regularisations. The pipe is the round
// member of the ducts of the Mosolov problem, the one with a closed form.
//
// Radius R, driven by G = −dp/dz > 0. The axial momentum balance
// (1/r) d(r τ_rz)/dr = −G gives τ(r) = G r/2, τ_w = G R/2 at the wall. The plug
// is r ≤ r0 = τ_y/(G/2) = φR with φ = τ_y/τ_w; outside it |dw/dr| = γ̇(G r/2), so
//
//     w(r) = ∫_r^R γ̇(G s/2) ds = (2/G) [Φ(τ_w) − Φ(G r/2)],    Φ(τ) = ∫₀^τ γ̇,
//
// and, integrating by parts,
//
//     Q = 2π ∫₀^R w r dr = π ∫₀^R r² γ̇(G r/2) dr = (8π/G³) ∫₀^{τ_w} τ² γ̇(τ) dτ,
//
// which for Herschel–Bulkley with φ < 1 is (macro.md)
//
//     Q = πR³ (τ_w/K)^{1/n} n (1−φ)^{(n+1)/n}
//           × [(1−φ)²/(3n+1) + 2φ(1−φ)/(2n+1) + φ²/(n+1)],
//
// and 0 for φ ≥ 1. Limits: Bingham, the Buckingham–Reiner formula
// Q = (πR⁴G/8μ)(1 − 4φ/3 + φ⁴/3); Newtonian, Hagen–Poiseuille Q = πR⁴G/(8μ).
//
// Wall slip by a law V_s(σ_w) (slip_law.h) leaves τ(r) as it is and shifts the
// profile by the uniform V_s(τ_w): Q = Q_no-slip + πR² V_s(GR/2).
#pragma once

#include "macro/exact/law_ref.h"
#include "macro/material/regularised_law.h"
#include "macro/material/slip_law.h"

namespace softglass::macro::exact {

struct Pipe {
  double radius = 1.0;             ///< R [m]
  double pressure_gradient = 1.0;  ///< G = −dp/dz [Pa/m], > 0
};

/// τ_w = G R/2 [Pa].
double wall_stress(const Pipe& pipe);

/// r0 = min(2τ_y/G, R) [m]: the plug is r ≤ r0.
double plug_radius(LawRef law, const Pipe& pipe);

/// Q [m³/s]; the wall slips by `wall` (null: no slip).
double flow_rate(LawRef law, const Pipe& pipe, const SlipLaw* wall = nullptr);

/// w(r) [m/s] for 0 ≤ r ≤ R.
double velocity(LawRef law, const Pipe& pipe, double r);

/// Q [m³/s] of the regularised problem (quadrature, numerics/quadrature.h).
double flow_rate(const RegularisedLaw& law, const Pipe& pipe);

/// w(r) [m/s] of the regularised problem (quadrature).
double velocity(const RegularisedLaw& law, const Pipe& pipe, double r);

}  // namespace softglass::macro::exact
