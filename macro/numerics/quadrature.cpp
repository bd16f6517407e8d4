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
  //
  // The integral runs over the offset s = x − a ∈ [0, b − a]: Boost's nodes
  // then resolve an interval that is narrow beside its distance from 0 (a
  // velocity a few nanometres from a wall: [19.999999996, 20] Pa), whose
  // absolute abscissae would otherwise round onto a handful of doubles and
  // leave the error estimate at rounding noise.
  std::size_t levels = 0;
  const auto shifted = [&f, a](double s) { return f(a + s); };
  const double value = integrator.integrate(shifted, 0.0, b - a, kQuadratureTolerance, nullptr,
                                            nullptr, &levels);
  if (levels >= kMaxLevels) {
    throw NumericalError(fmt::format(
        "quadrature on [{}, {}] did not reach its relative tolerance {} in {} levels", a, b,
        kQuadratureTolerance, kMaxLevels));
  }
  return value;
}

double integrate(const std::function<double(double)>& f, double a, double b,
                 std::vector<double> cuts) {
  std::erase_if(cuts, [&](double c) { return !(c > a && c < b); });
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0, from = a;
  for (const double c : cuts) {
    sum += integrate(f, from, c);
    from = c;
  }
  return sum + integrate(f, from, b);
}

}  // namespace softglass::macro::numerics
