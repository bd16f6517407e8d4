// The tabulated law: a flow curve given point by point — the simulated
// σ(γ̇), N1(γ̇), N2(γ̇) of the particles, handed to the continuum whole
// (`bridge material --tabulated`) instead of squeezed into one
// Herschel–Bulkley triple.
//
// The table: the yield stress τ_y ≥ 0 (the quasi-static limit γ̇ → 0) and M ≥ 2
// rates γ̇_1 < … < γ̇_M with stresses τ_1 < … < τ_M, τ_1 > τ_y.
//
// Interpolation. The excess stress Δ = τ − τ_y of a soft glass is close to a
// power of the rate over decades (Δ ∝ γ̇^{~½}), so the table is interpolated in
// the variables that make a power law a straight line,
//
//     ln Δ(γ̇) = P(ln γ̇),   P the monotone cubic of (ln γ̇_i, ln Δ_i)
//
// (numerics/monotone_cubic.h). P is C¹, increasing because the data are, and
// never overshoots them; its slope is the local flow index n(γ̇) = d ln Δ/d ln γ̇.
// A table sampled from a Herschel–Bulkley law lies on a straight line in these
// variables, and the interpolant then *is* that law, to rounding.
//
// Outside the window [γ̇_1, γ̇_M] the law is extrapolated, and says so
// (description()): a power law continuing the mean exponent of the
// end interval, n_lo = ln(Δ_2/Δ_1)/ln(γ̇_2/γ̇_1) below and likewise n_hi above,
//
//     Δ(γ̇) = Δ_1 (γ̇/γ̇_1)^{n_lo}  (γ̇ < γ̇_1),   Δ(γ̇) = Δ_M (γ̇/γ̇_M)^{n_hi}  (γ̇ > γ̇_M).
//
// Below the window that is the approach to the quasi-static yield stress
// (Δ → 0 as γ̇ → 0, the same continuation as a Herschel–Bulkley fit of the low
// rates); both continuations keep P's slope continuous at the window's ends.
// Both end exponents must lie in (0, 2], the range of a material file's flow
// index, so that the extrapolated law stays one the solvers handle.
//
// Normal stress differences N1, N2 (optional, at the same rates, any sign),
// with their limits N_y at rest: inside the window the monotone cubic of
// (ln γ̇_i, N_i), which cannot overshoot noisy data; outside, the excess
// N − N_y scales with the same end exponents as the shear stress (the normal
// stresses of soft glasses follow the shear stress's rate dependence, Seth et
// al. 2011: N1/σ_y and N2/σ_y obey the universal law with exponent ½ too).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "macro/material/normal_stress.h"
#include "macro/material/shear_law.h"

namespace softglass::macro {

struct FlowTable {
  double yield_stress = 0.0;     ///< τ_y [Pa] ≥ 0, the limit γ̇ → 0
  std::vector<double> rates;     ///< γ̇_i [1/s] > 0, strictly increasing
  std::vector<double> stresses;  ///< τ_i [Pa], strictly increasing, τ_1 > τ_y
};

/// The law of `table`; InputError naming the entry (as the material file
/// spells it: rates, stresses, yield stress) and the offending row otherwise.
std::shared_ptr<const ShearLaw> tabulated_law(const FlowTable& table);

/// A normal stress difference tabulated at the rates of `table` (`values`, one
/// per rate) with limit `rest` at γ̇ → 0. `name` (N1, N2) names it in errors.
std::shared_ptr<const NormalStressCurve> tabulated_normal_stress(const FlowTable& table,
                                                                 double rest,
                                                                 std::vector<double> values,
                                                                 const std::string& name);

}  // namespace softglass::macro
