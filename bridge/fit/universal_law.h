// The paper's universal laws (its Fig. 4), fitted over all volume fractions at once.
//
// Shear stress: σ/σ_y = 1 + k (γ̃/γ_y²)^½ with γ_y = σ_y/G0 is
//     σ_ij = σ_y,j + k G0_j √γ̃_i,
// one k for every φ_j, one free yield stress σ_y,j per φ_j, G0_j measured.
//
// Normal stress differences, scaled by the same σ_y:
//     N1/σ_y = N1_y/σ_y + k′ (γ̃/γ_y²)^½,   −N2/σ_y = −N2_y/σ_y + k″ (γ̃/γ_y²)^½,
// which is N_ij = N_y,j ± k′ G0_j √γ̃_i (− for N2, which falls with the rate),
// one k′ (k″) and one free plateau N_y,j per φ_j. The paper leaves the scale
// open ("similar relationships"); σ_y is the one its Fig. 5 uses, rescaling
// measured N1 with σ_y, γ_y and E* alone, and it makes k′/k the ratio N1/σ of
// the rate terms (the paper: 20/80; N1/σ → 0.2–0.26 at γ̃ = 1e-4 in our
// sweeps). The alternative N/N_y = 1 + k′ (…)^½ divides by a plateau that the
// simulations do not resolve from zero at most φ, and k′ then diverges.
//
// All three are one linear model Q_ij = a_j + k α_j √γ̃_i (α = ±G0), weighted
// by the standard errors. The free a_j absorb each φ's yield value, so k
// measures only whether the rate terms collapse: k_Q,j/G0_j the same for all φ.
#pragma once

#include <string>
#include <vector>

#include "bridge/fit/curve.h"
#include "bridge/fit/least_squares.h"

namespace softglass::bridge {

struct UniversalFit {
  double k = 0.0;
  std::vector<double> yield;  // a_j: σ_y,j or N_y,j
  GoodnessOfFit goodness;
  bool converged = false;
  std::string status;
};

/// `curves[j]` is Q/E* against γ̃ at φ_j, `modulus[j]` its G0/E*; `sign` is
/// +1 for σ and N1 and −1 for N2, so that k, k′ and k″ are all positive.
UniversalFit fit_universal_law(const std::vector<const Curve*>& curves,
                               const std::vector<double>& modulus, double sign);

/// The collapse variable γ̃/γ_y² of the universal laws.
inline double collapse_rate(double gamma_tilde, double yield_strain) {
  return gamma_tilde / (yield_strain * yield_strain);
}

}  // namespace softglass::bridge
