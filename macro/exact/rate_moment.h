// ∫ τ^k γ̇_ε(τ) dτ for a regularised law: the one integral behind the channel
// and pipe solutions of regularised problems (exact/channel.h, exact/pipe.h),
// whose flow rates are its moments k = 1, 2 and whose velocities its k = 0.
#pragma once

#include "macro/material/regularised_law.h"

namespace softglass::macro::exact {

/// ∫_from^to τ^power γ̇_ε(τ) dτ, 0 ≤ from ≤ to, with γ̇_ε = law.rate(τ). The
/// regularised rate turns steeply near the yield stress of law.law() (within
/// a stress range that shrinks with ε), so the interval is split there and the
/// quadrature of numerics/quadrature.h sees the turn only at an end.
double rate_moment(const RegularisedLaw& law, int power, double from, double to);

}  // namespace softglass::macro::exact
