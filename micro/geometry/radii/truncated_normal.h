// The standard normal distribution truncated to [−c, c]: what the gaussian and
// lognormal shapes need to keep sd/mean at the requested polydispersity.
#pragma once

#include <cmath>
#include <numbers>
#include <random>

namespace softglass::micro {

/// Standard normal distribution function.
inline double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::numbers::sqrt2);
}

/// Variance of a standard normal truncated to [−c, c]: 1 − 2cφ(c)/(2Φ(c) − 1).
inline double truncated_normal_variance(double c) {
  const double density = std::exp(-0.5 * c * c) / std::sqrt(2.0 * std::numbers::pi);
  return 1.0 - 2.0 * c * density / (2.0 * normal_cdf(c) - 1.0);
}

/// E[e^{tZ}] for Z standard normal truncated to [−c, c].
inline double truncated_normal_mgf(double t, double c) {
  return std::exp(0.5 * t * t) * (normal_cdf(c - t) - normal_cdf(-c - t)) /
         (2.0 * normal_cdf(c) - 1.0);
}

/// A draw of the standard normal truncated to [−c, c] (rejection).
inline double truncated_normal(std::normal_distribution<double>& normal, std::mt19937_64& rng,
                               double c) {
  double z;
  do z = normal(rng);
  while (std::abs(z) > c);
  return z;
}

}  // namespace softglass::micro
