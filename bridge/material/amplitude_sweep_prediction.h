// A material's amplitude sweep from the law's (law/amplitude_sweep.h), in SI
// units: G′ = E* G̃′(φ, γ0) and G″ = E* G̃″(φ, γ0) at the frequency the law
// was simulated at, ω = ω̃ E*/η_s; and, the other way round, E* from a
// measured G′ plateau through the same numbers.
//
// The moduli are interpolated between the sweep's volume fractions like the
// law's other per-φ values (material.h: in logarithm, with statistical and
// interpolation errors); the strains of softening and crossover likewise. In
// a narrow-gap Couette cell or a cone and plate the strain is nearly
// homogeneous, so this is what the instrument reports; for the castor-oil
// Couette cell of ../shared/data/rheometry (R2/R1 = 1.086) the strain varies
// by ±8 % across the gap, which smears the crossover by as much.
#pragma once

#include <vector>

#include "bridge/material/material.h"

namespace softglass::bridge {

struct AmplitudeSweepPrediction {
  double reduced_frequency = 0.0;                    // the law's ω̃
  double angular_frequency = 0.0;                    // ω = ω̃ E*/η_s [rad/s]
  std::vector<double> amplitudes;                    // γ0
  std::vector<MaterialValue> storage, loss;          // [Pa]
  MaterialValue plateau_storage, plateau_loss;       // [Pa], at the smallest amplitude
  MaterialValue softening_strain, crossover_strain;  // 0: not reached within the sweep
};

/// The amplitude sweep at (φ, E*, η_s); InputError when the law has none or φ
/// is out of its range (unless `extrapolate`).
AmplitudeSweepPrediction predict_amplitude_sweep(const Law& law, const MaterialRequest& request);

/// E* = G′_measured / (G̃′ plateau)(φ), the law's oscillatory plateau; its
/// errors carry over relatively.
MaterialValue contact_modulus_from_amplitude_sweep(const Law& law, double phi,
                                                   double plateau_modulus, bool extrapolate);

}  // namespace softglass::bridge
