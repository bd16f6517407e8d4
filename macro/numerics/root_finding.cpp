#include "macro/numerics/root_finding.h"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

#include "common/errors.h"

namespace softglass::macro::numerics {

namespace {

// Widening steps allowed: 2^±100 is far beyond any physical bracket error.
constexpr int kMaxWidening = 100;
// TOMS 748 needs a handful of iterations at full precision; this is a safety cap.
constexpr std::uintmax_t kMaxIterations = 200;
// The widest bracket handed to TOMS 748 (below).
constexpr double kMaxBracketRatio = 4.0;

}  // namespace

double solve_increasing(const std::function<double(double)>& f, double lo, double hi,
                        std::string_view what) {
  double f_lo = f(lo), f_hi = f(hi);
  for (int k = 0; f_lo > 0.0 && k < kMaxWidening; ++k) f_lo = f(lo *= 0.5);
  for (int k = 0; f_hi < 0.0 && k < kMaxWidening; ++k) f_hi = f(hi *= 2.0);
  // TOMS 748 interpolates f across the bracket; over many orders of magnitude
  // (an f of 1e-3 at lo and 1e268 or +inf where it overflows at hi) its
  // interpolants overflow to NaN. Bisect geometrically, keeping the root
  // bracketed, until hi/lo is modest and f(hi) finite: log(hi/lo) halves at
  // every step. (The solvers' own calls start at lo = 0 and never enter.)
  for (int k = 0; lo > 0.0 && (hi > kMaxBracketRatio * lo || std::isinf(f_hi)) && k < kMaxWidening;
       ++k) {
    const double mid = std::sqrt(lo) * std::sqrt(hi), f_mid = f(mid);
    (f_mid < 0.0 ? lo : hi) = mid;
    (f_mid < 0.0 ? f_lo : f_hi) = f_mid;
  }
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if (!(f_lo < 0.0 && f_hi > 0.0)) {
    throw NumericalError(fmt::format("{}: no root found in [{}, {}]", what, lo, hi));
  }
  std::uintmax_t iterations = kMaxIterations;
  const auto converged = [](double a, double b) {
    return std::abs(b - a) <= kRootTolerance * std::max(std::abs(a), std::abs(b));
  };
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, converged, iterations);
  if (!converged(a, b)) {
    throw NumericalError(
        fmt::format("{}: root finding stopped after {} iterations at [{}, {}]", what, iterations, a, b));
  }
  return 0.5 * (a + b);
}

}  // namespace softglass::macro::numerics
