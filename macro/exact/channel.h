// Plane Poiseuille flow: the exact solution for any shear law and for its
// regularisations, by quadrature of the inverse flow curve.
//
// Walls at y = ±H, driven by G = −dp/dx > 0. The x-momentum balance
// dτ_xy/dy = −G with symmetry about the axis gives the shear stress
// τ(y) = G|y|, zero on the axis and τ_w = GH at the walls, whatever the law.
// Where G|y| ≤ τ_y the material moves as a rigid plug, |y| ≤ y0 = τ_y/G; outside
// it |du/dy| = γ̇(G|y|), the inverse flow curve. No slip at the walls gives
//
//     u(y) = ∫_{|y|}^{H} γ̇(G s) ds = [Φ(τ_w) − Φ(G|y|)] / G,    Φ(τ) = ∫₀^τ γ̇,
//
// flat in the plug. Integrating by parts, the
// flow rate per unit width through the whole channel is
//
//     Q = 2 ∫₀^H u dy = 2 ∫₀^H y γ̇(G y) dy = (2/G²) ∫₀^{τ_w} τ γ̇(τ) dτ,
//
// both evaluated by quadrature (rate_moment.h). For Herschel–Bulkley, with
// φ = τ_y/τ_w < 1, that is (macro.md; the tests)
//
//     Q = 2H² (τ_w/K)^{1/n} n (1−φ)^{(n+1)/n} [(1−φ)/(2n+1) + φ/(n+1)],
//
// and Q = 0 for φ ≥ 1 (the whole channel is a plug stuck to the walls).
// Limits: Bingham (Buckingham) Q = (2GH³/3μ)(1 − 3φ/2 + φ³/2); power law
// Q = 2H²(τ_w/K)^{1/n} n/(2n+1); Newtonian Q = 2GH³/(3μ), u = G(H² − y²)/(2μ).
//
// Wall slip. If both walls slip by a law V_s(σ_w) (slip_law.h), the stress
// profile is unchanged — τ_w = GH is fixed by the balance alone — and the
// material at the walls moves at V_s(GH): the profile above shifts by that
// uniform velocity, the plug included, and
//
//     u(y) = V_s(GH) + [Φ(τ_w) − Φ(G|y|)] / G,     Q = Q_no-slip + 2H V_s(GH).
//
// Without a slip yield stress the channel flows under any G, as a sliding
// plug below the yield stress (φ ≥ 1).
//
// A regularised law has no plug (γ̇_ε > 0 wherever τ > 0); the same two
// integrals, evaluated by quadrature (rate_moment.h), give the exact solution
// of the regularised problem. A regularised FE solver should converge to that
// at its discretisation order, and that to the above as ε → 0 (at O(ε)).
#pragma once

#include "macro/exact/law_ref.h"
#include "macro/material/regularised_law.h"
#include "macro/material/slip_law.h"

namespace softglass::macro::exact {

struct PlaneChannel {
  double half_height = 1.0;        ///< H [m]
  double pressure_gradient = 1.0;  ///< G = −dp/dx [Pa/m], > 0
};

/// τ_w = G H [Pa].
double wall_stress(const PlaneChannel& channel);

/// y0 = min(τ_y/G, H) [m]: the plug is |y| ≤ y0.
double plug_half_width(LawRef law, const PlaneChannel& channel);

/// Q [m²/s], the flow rate per unit width (spanwise); both walls slip by
/// `wall` (null: no slip).
double flow_rate(LawRef law, const PlaneChannel& channel,
                 const SlipLaw* wall = nullptr);

/// u(y) [m/s] for |y| ≤ H; both walls slip by `wall` (null: no slip).
double velocity(LawRef law, const PlaneChannel& channel, double y,
                const SlipLaw* wall = nullptr);

/// Q [m²/s] of the regularised problem (quadrature, numerics/quadrature.h).
double flow_rate(const RegularisedLaw& law, const PlaneChannel& channel);

/// u(y) [m/s] of the regularised problem (quadrature).
double velocity(const RegularisedLaw& law, const PlaneChannel& channel, double y);

}  // namespace softglass::macro::exact
