// Shear-induced layering: the order parameter that tells a sheared glass from a
// sample that has ordered into layers sliding over each other.
//
//     S_y = max_{m = 1 … M} |Σ_α exp(2πi m y_α / L)|² / N ,   M = ⌊L / R⌋,
//
// the largest static structure factor along the gradient direction y. For
// disordered positions each term is exponentially distributed with mean 1, so
// the maximum of M ≈ 17 terms (N = 1000) is about 3.4; layers of spacing L/m
// make the m-th term grow like N. A sheared dense glass fluctuates above the
// random value (measured at φ = 0.80, γ̃ = 1e-4, δ = 0.15: S_y ≈ 10, up to 27
// averaged over 2 strain), while a sample that layers goes on to 10²…10³ (δ =
// 0.10: N = 1000 and 4000 alike, the stress falling by half over 60 strain).
// Runs report S_y; above kLayeredThreshold a sample counts as layered.
#pragma once

#include <span>

#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

/// Above this S_y a sample counts as layered (see above).
inline constexpr double kLayeredThreshold = 50.0;

struct Layering {
  double order = 0.0;  // S_y
  int layers = 0;      // the m of the maximum: number of layers across the cell
};

/// Positions need not be wrapped (S_y is periodic in y with period L).
Layering gradient_layering(std::span<const Vec3> positions, double side);

}  // namespace softglass::micro
