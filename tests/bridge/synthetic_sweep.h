// Synthetic sweeps with known parameters: the paper's laws plus realistic
// packing-to-packing noise, as the particle engine's sweeps will write them.
//
// Truth, per volume fraction φ_j with shear modulus G0_j and yield strain γ_y,j:
//     σ_y = G0 γ_y,                σ   = σ_y (1 + k  √γ̃ / γ_y)
//     N1_y = r1 σ_y,               N1  = N1_y + k′ σ_y √γ̃ / γ_y
//     N2_y = r2 σ_y,               N2  = N2_y − k″ σ_y √γ̃ / γ_y
//     f_m = f_y + k_f √γ̃ with f_y = c_y G0, k_f = c_k G0,
// i.e. Herschel–Bulkley laws with m = ½ and k_σ = k G0. Every run (φ, γ̃, seed)
// draws each value with an independent Gaussian relative error; every packing
// (φ, seed) draws its G0 likewise. The table averages the runs of each state
// point, with standard errors s/√K, as `micro summary` does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bridge/io/flow_curve_table.h"
#include "bridge/law/law.h"

namespace softglass::bridge::testing {

struct SyntheticTruth {
  std::vector<double> phi{0.70, 0.75, 0.80, 0.85, 0.90};
  std::vector<double> modulus{0.030, 0.055, 0.085, 0.12, 0.16};         // G0/E*
  std::vector<double> yield_strain{0.040, 0.034, 0.029, 0.024, 0.020};  // the paper: 0.02 … 0.04
  double k = 80.0, k_N1 = 20.0, k_N2 = 26.0;                            // the paper's values
  double N1_ratio = 0.4, N2_ratio = -0.6;                               // N_y / σ_y
  double force_yield = 0.5, force_slope = 100.0;                        // f_y/G0, k_f/G0
  std::vector<double> gamma_tilde;  // default: 1e-9 … 1e-4, two per decade
  std::size_t packings = 5;
  // Relative standard deviations per run (per packing for G0). Our engine's
  // φ = 0.80 runs: σ 0.1–2 %, N1 5–13 %, N2 1.5–4 %, G0 7 % (docs/validation.md).
  double sigma_noise = 0.02, normal_noise = 0.06, modulus_noise = 0.07, force_noise = 0.02;
  bool normal = true, force = true;

  SyntheticTruth();
  double sigma_yield(std::size_t j) const { return modulus[j] * yield_strain[j]; }
  double sigma(std::size_t j, double gamma_tilde) const;
  double normal_yield(std::size_t j, Quantity q) const;
  double value(std::size_t j, Quantity q, double gamma_tilde) const;
};

struct SyntheticSweep {
  FlowCurveTable table;
  std::vector<PackingRun> runs;
};

SyntheticSweep make_synthetic_sweep(const SyntheticTruth& truth, std::uint64_t seed);

/// The truth as a law, exactly (no fit), with fixed relative errors: 3 % on G0
/// and γ_y, 1 % on yield values, 10 % on consistencies, 0.01 on exponents.
Law exact_law(const SyntheticTruth& truth);

/// The sweep as the two CSV files of docs/flow-curve-format.md.
std::string table_csv(const SyntheticSweep& sweep);
std::string runs_csv(const SyntheticSweep& sweep);
/// Its f_m as a companion structure table (phi, gamma_tilde, f_m, f_m_se).
std::string structure_csv(const SyntheticSweep& sweep);
/// The sweep with the structure columns taken out of both tables.
SyntheticSweep without_structure(SyntheticSweep sweep);
/// The sweep plus a quasi-static row (γ̃ = 0: the yield values, as an AQS case
/// gives them) per φ and its runs, drawn from `seed` with the sweep's noise
/// (G0 redrawn too); the other rows unchanged.
SyntheticSweep with_quasi_static(SyntheticSweep sweep, SyntheticTruth truth, std::uint64_t seed);

}  // namespace softglass::bridge::testing
