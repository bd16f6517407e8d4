#include "bridge/law/crossover_estimate.h"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

// ∫_a^b of sin, sin², cos and sin·cos.
double sin_integral(double a, double b) { return std::cos(a) - std::cos(b); }
double sin2_integral(double a, double b) {
  return 0.5 * (b - a) - 0.25 * (std::sin(2 * b) - std::sin(2 * a));
}
double cos_integral(double a, double b) { return std::sin(b) - std::sin(a); }
double sincos_integral(double a, double b) {
  return 0.5 * (std::pow(std::sin(b), 2) - std::pow(std::sin(a), 2));
}

}  // namespace

ElastoplasticModuli elastoplastic_moduli(double x) {
  require(std::isfinite(x) && x > 0, "elastoplastic_moduli: the amplitude ratio must be positive");
  if (x <= 1.0) return {};
  using std::numbers::pi;
  const double top = 0.5 * pi, bottom = 1.5 * pi;
  const double flow = pi - std::asin(1.0 - 2.0 / x);  // θ₁: the unloading reaches −σ_f
  // Unloading σ/σ_f = (1 − x) + x sin θ on [π/2, θ₁], flow at −1 on [θ₁, 3π/2].
  const double sine = (1 - x) * sin_integral(top, flow) + x * sin2_integral(top, flow) -
                      sin_integral(flow, bottom);
  const double cosine = (1 - x) * cos_integral(top, flow) + x * sincos_integral(top, flow) -
                        cos_integral(flow, bottom);
  return {2 / pi * sine / x, 2 / pi * cosine / x};
}

double elastoplastic_crossover_ratio() {
  // G′ − G″ is 1 at x = 1 and negative at x = 10 (0.052 − 0.115): G″ falls
  // like 4/(πx), G′ faster, like x^{−3/2}.
  static const double ratio = [] {
    const auto difference = [](double x) {
      const ElastoplasticModuli m = elastoplastic_moduli(x);
      return m.storage - m.loss;
    };
    boost::math::tools::eps_tolerance<double> tolerance(50);
    std::uintmax_t iterations = 100;
    const auto [low, high] =
        boost::math::tools::toms748_solve(difference, 1.0, 10.0, tolerance, iterations);
    return 0.5 * (low + high);
  }();
  return ratio;
}

double crossover_strain_estimate(double yield_strain, double k, double reduced_frequency) {
  require(std::isfinite(yield_strain) && yield_strain > 0,
          "crossover estimate: the yield strain must be positive");
  require(std::isfinite(k) && k >= 0, "crossover estimate: k must be non-negative");
  require(std::isfinite(reduced_frequency) && reduced_frequency >= 0,
          "crossover estimate: the reduced frequency must be non-negative");
  const double x = elastoplastic_crossover_ratio();
  const double a = x * k * std::sqrt(reduced_frequency);
  const double s = 0.5 * (a + std::sqrt(a * a + 4 * x * yield_strain));
  return s * s;
}

}  // namespace softglass::bridge
