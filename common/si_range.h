// The magnitudes every tool accepts and writes for a dimensional quantity in
// SI units: zero, or between 1e-100 and 1e100. macro's solves form squares and
// products of their scales (norms, r³η), which stay finite only within it
// (macro/app/input_scales.h); bridge holds what it writes to the same range, so
// that a material it accepts is never refused one step later by macro.
#pragma once

#include <cmath>

namespace softglass {

inline constexpr double kSiRange = 1e100;

/// Zero, or finite with 1/kSiRange <= |value| <= kSiRange.
inline bool within_si_range(double value) {
  const double a = std::abs(value);
  return a == 0.0 || (std::isfinite(a) && a >= 1.0 / kSiRange && a <= kSiRange);
}

}  // namespace softglass
