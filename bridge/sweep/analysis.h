// `bridge fit` from start to finish: fit the sweep, refuse what cannot be
// fitted, bootstrap the uncertainties and say what is poorly determined.
//
// Refused (InputError): a volume fraction whose shear stress shows no yield
// plateau (fit/herschel_bulkley.h, check_plateau) — its σ_y, γ_y and everything
// built on them would be extrapolations. Failed (NumericalError): the
// Herschel–Bulkley fit of σ or the universal stress fit does not converge.
// Everything else that is doubtful becomes a warning:
//   - state points averaging runs that did not meet their stopping rule
//     (`converged` < `packings` in the table);
//   - a law that misses its data: p-value of χ² below 0.001 (with about 15 fits
//     per sweep this flags a correct law in about 1.5 % of sweeps);
//   - volume fractions that do not collapse: each φ's own constant (sweep_fit.h)
//     compared with their weighted mean by Cochran's homogeneity test,
//     Q = Σ_j (k_j − k̄)²/SE(k_j)² against χ² with J − 1 degrees of freedom, the
//     SE from the bootstrap. (The χ² of the universal fit itself cannot serve:
//     it takes G0 as exact, but G0 is known to a few per cent only and its
//     error moves each φ's rate term as a whole; the bootstrap SE includes it.)
//   - a yield value or a universal constant known to worse than a quarter of
//     its value, or an exponent known to worse than ±0.1;
//   - N1, N2 or f_m without a yield plateau, or whose fit failed;
//   - numbers that failed in more than 1 % of the bootstrap replicates.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bridge/sweep/bootstrap.h"

namespace softglass::bridge {

struct SweepAnalysis {
  Sweep sweep;
  SweepFitOutcome estimate;
  BootstrapResult uncertainty;
  std::string method;                   // how the uncertainties were obtained
  PerQuantity<GoodnessOfFit> collapse;  // sigma, N1, N2: Cochran's test over φ
  std::vector<std::string> warnings;
};

SweepAnalysis analyse_sweep(const Sweep& sweep, const Resampler& resampler,
                            const BootstrapOptions& options,
                            const std::function<void(std::size_t)>& progress = {});

}  // namespace softglass::bridge
