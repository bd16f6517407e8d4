// ∫ τ^k γ̇(τ) dτ: the one integral behind the channel and pipe solutions
// (exact/channel.h, exact/pipe.h), whose flow rates are its moments k = 1, 2
// and whose velocities its k = 0 — of a shear law, and of its regularisation.
#pragma once

#include "macro/material/regularised_law.h"
#include "macro/material/shear_law.h"

namespace softglass::macro::exact {

/// ∫_from^to τ^power γ̇_ε(τ) dτ, 0 ≤ from ≤ to, with γ̇_ε = law.rate(τ). The
/// regularised rate turns steeply near the yield stress of law.law() (within
/// a stress range that shrinks with ε), so the interval is split there and the
/// quadrature of numerics/quadrature.h sees the turn only at an end.
double rate_moment(const RegularisedLaw& law, int power, double from, double to);

/// ∫_from^to τ^power γ̇(τ) dτ, 0 ≤ from ≤ to, of a shear law: zero below its
/// yield stress, and integrated in the excess stress e = τ − τ_y above it
/// (ShearLaw::rate_at_excess: no digits lost to a thin yielded layer), split
/// at the law's breakpoints.
double rate_moment(const ShearLaw& law, int power, double from, double to);

}  // namespace softglass::macro::exact
