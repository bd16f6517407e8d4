// Roots of increasing scalar functions, for the inverse problems of the exact
// references (torque from rotation rate), of the regularised laws (shear rate
// from stress) and for the local step of augmented-Lagrangian solvers.
//
// Every such function is continuous and increasing on the positive axis, so a
// bracketing method cannot fail once the root is bracketed: TOMS Algorithm 748
// (Alefeld, Potra & Shi 1995; boost::math::tools::toms748_solve) keeps the
// bracket of bisection and converges superlinearly by inverse cubic
// interpolation.
#pragma once

#include <functional>
#include <string_view>

namespace softglass::macro::numerics {

/// Relative width of the final bracket: solve_increasing() returns x with
/// |x − x*| ≤ kRootTolerance·x*. Far below the quadrature tolerance, so that an
/// inverse computed from a quadrature is limited by the quadrature alone.
inline constexpr double kRootTolerance = 1e-13;

/// The root x* of an increasing f on [lo, hi], 0 ≤ lo ≤ hi. If f(lo) > 0 or
/// f(hi) < 0 the bracket is first widened geometrically (lo halved towards 0, hi
/// doubled), so a bracket that is only almost right does no harm; a bracket
/// over orders of magnitude is first narrowed by geometric bisection, and f may
/// be +inf where it overflows. `what` names
/// the problem in the NumericalError thrown if no root is found.
double solve_increasing(const std::function<double(double)>& f, double lo, double hi,
                        std::string_view what);

}  // namespace softglass::macro::numerics
