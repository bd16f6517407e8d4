#include "macro/numerics/quadrature.h"

#include <fmt/format.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "common/errors.h"

namespace softglass::macro::numerics {

namespace {

// Each level halves the node spacing; 15 (Boost's default) is far more than a
// smooth integrand needs (4–6 for 1e-10).
constexpr std::size_t kMaxLevels = 15;
// Relative width below which an interval counts as degenerate: 64 ulps.
constexpr double kDegenerateWidth = 64.0 * std::numeric_limits<double>::epsilon();

}  // namespace

double integrate(const std::function<double(double)>& f, double a, double b) {
  // An interval a few ulps wide (a yield point that rounds onto an end) holds
  // no room for nodes; the midpoint rule is exact to rounding there.
  if (b - a <= kDegenerateWidth * std::max(std::abs(a), std::abs(b))) return (b - a) * f(0.5 * (a + b));
  // The integrator keeps its abscissa tables and extends them on demand, so
  // one per thread is built once and reused.
  thread_local boost::math::quadrature::tanh_sinh<double> integrator(kMaxLevels);
  // Boost stops refining as soon as its estimate (the change between the last
  // two levels) is below the tolerance times ∫|f|, and otherwise runs out of
  // levels; that is the test used here. (Boost 1.74 returns the estimate on the
  // reference interval [−1, 1] but ∫|f| on [a, b], so the two returned values
  // are not comparable as they stand.)
  std::size_t levels = 0;
  const double value =
      integrator.integrate(f, a, b, kQuadratureTolerance, nullptr, nullptr, &levels);
  if (levels >= kMaxLevels) {
    throw NumericalError(fmt::format(
        "quadrature on [{}, {}] did not reach its relative tolerance {} in {} levels", a, b,
        kQuadratureTolerance, kMaxLevels));
  }
  return value;
}

}  // namespace softglass::macro::numerics
