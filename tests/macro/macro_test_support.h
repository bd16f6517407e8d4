// Helpers shared by the macro tests.
#pragma once

#include <cmath>
#include <functional>

#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace softglass::macro::testing {

// An integration oracle independent of the library's tanh–sinh quadrature:
// adaptive 61-point Gauss–Kronrod after a polynomial change of variables.
//
// The integrands of the exact references behave like |x − c|^α at an end c of
// the interval (the inverse flow curve ((τ − τ_y)/K)^{1/n} at the yield stress,
// α = 1/n down to 0.625 here). Gauss–Kronrod converges only algebraically on
// such a function, and adaptive bisection down to 1e-13 then takes 2^20
// intervals (too slow for a unit test, as the old version of this helper
// was). The map
//
//     x = a + (b − a) S(t),   S(t) = 35t⁴ − 84t⁵ + 70t⁶ − 20t⁷,   S'(t) = 140 t³(1 − t)³,
//
// (the regularised incomplete beta function I_t(4, 4)) is a bijection of [0, 1]
// onto [a, b] with x − a ≈ 35t⁴ near t = 0 (and likewise at t = 1), so an end
// behaviour |x − c|^α becomes t^{4α + 3}: smooth enough (t^5.5 at worst) that
// Gauss–Kronrod meets 1e-13 in a few subdivisions. Smooth integrands stay smooth.
inline double gauss_kronrod(const std::function<double(double)>& f, double a, double b) {
  if (a == b) return 0.0;
  const auto mapped = [&](double t) {
    const double t2 = t * t, s = t2 * t2 * (35.0 - t * (84.0 - t * (70.0 - 20.0 * t)));
    const double u = t * (1.0 - t);
    return f(a + (b - a) * s) * (b - a) * 140.0 * u * u * u;
  };
  return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(mapped, 0.0, 1.0, 20, 1e-13);
}

inline double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

}  // namespace softglass::macro::testing
