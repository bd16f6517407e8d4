// Adaptive quadrature for the exact references.
//
// The integrands of the rheometer solutions are smooth inside their intervals
// but often not at the ends: the inverse flow curve γ̇(τ) = ((τ − τ_y)/K)^{1/n}
// has an algebraic singularity at the yield stress (a square root for n = 2, an
// unbounded second derivative for n = 0.6), and callers cut every interval at
// the yield point so that it only ever sits at an end. Tanh–sinh (double
// exponential) quadrature is built for exactly this: it clusters its nodes
// doubly exponentially towards both ends and converges exponentially in the
// number of nodes for integrands analytic inside the interval, whatever the
// algebraic behaviour at the ends (Takahasi & Mori 1974; boost::math).
#pragma once

#include <functional>
#include <vector>

namespace softglass::macro::numerics {

/// Requested relative accuracy of integrate(): the tanh–sinh estimate (the
/// change between the last two refinement levels) must fall below this times
/// ∫|f|. The estimate is pessimistic — at convergence the error is roughly its
/// square — so results are usually accurate to 1e-14 (measured against the
/// closed forms in tests/macro).
inline constexpr double kQuadratureTolerance = 1e-10;

/// ∫_a^b f(x) dx for a ≤ b, f finite on (a, b) and analytic inside (endpoint
/// singularities are fine). Throws NumericalError if the tolerance is not met
/// within 15 refinement levels (then f has a kink or a jump inside: split the
/// interval there).
double integrate(const std::function<double(double)>& f, double a, double b);

/// The same, split at the `cuts` that lie inside (a, b) (any order): the points
/// where f is only finitely smooth, such as the nodes of a tabulated law, so
/// that each piece is analytic inside and keeps the exponential convergence.
double integrate(const std::function<double(double)>& f, double a, double b,
                 std::vector<double> cuts);

}  // namespace softglass::macro::numerics
