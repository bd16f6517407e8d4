// The paper's universal laws (its Fig. 4), fitted over all volume fractions at once.
//
// Shear stress: σ/σ_y = 1 + k (γ̃/γ_y²)^½ with γ_y = σ_y/G0 is
//     σ_ij = σ_y,j + k G0_j √γ̃_i,
// one k for every φ_j, one free yield stress σ_y,j per φ_j, G0_j measured.
// Normal stress differences: N/N_y = 1 + k′ (γ̃/γ_y²)^½, with γ_y,j taken from
// the stress law, is
//     N_ij = N_y,j (1 + k′ √γ̃_i / γ_y,j),
// one k′ (k″ for N2) and one free N_y,j per φ_j.
//
// Both are the one model Q_ij = a_j + k (α_j + β_j a_j) √γ̃_i (stress: α = G0,
// β = 0; normal: α = 0, β = 1/γ_y), weighted by the standard errors. The free
// a_j absorb each φ's yield value, so k measures only whether the rate terms
// collapse: k_σ,j/G0_j (stress) or k_N,j γ_y,j/N_y,j (normal) the same for all φ.
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

/// `curves[j]` is σ/E* against γ̃ at φ_j, `modulus[j]` its G0/E*.
UniversalFit fit_universal_stress(const std::vector<const Curve*>& curves,
                                  const std::vector<double>& modulus);

/// `curves[j]` is N/E* against γ̃ at φ_j, `yield_strain[j]` the γ_y,j of the stress law.
UniversalFit fit_universal_normal(const std::vector<const Curve*>& curves,
                                  const std::vector<double>& yield_strain);

/// The collapse variable γ̃/γ_y² of the universal laws.
inline double collapse_rate(double gamma_tilde, double yield_strain) {
  return gamma_tilde / (yield_strain * yield_strain);
}

}  // namespace softglass::bridge
