// Harmonic analysis of oscillatory shear, γ(t) = γ0 sin ωt: the moduli and
// higher harmonics of each cycle, and the periodic state over cycles.
//
// Each cycle is sampled at N equally spaced phases θ_k = 2πk/N (k = 0 … N−1).
// A scalar response s(θ) has the Fourier series
//     s(θ) = s_0 + Σ_n (s′_n sin nθ + s″_n cos nθ),
//     s′_n = (2/N) Σ_k s_k sin nθ_k,   s″_n = (2/N) Σ_k s_k cos nθ_k,
// exact for a signal without harmonics at or above N/2 (the trapezoidal rule
// is spectrally accurate for periodic functions; above N/2 they alias).
//
// For the shear stress, σ(t) = γ0 Σ_{n odd} (G′_n sin nωt + G″_n cos nωt)
// (Ewoldt, Hosoi & McKinley, J. Rheol. 52, 1427 (2008)): G′ = G′_1 and
// G″ = G″_1 are the storage and loss moduli a rheometer reports, the relative
// intensities I_n/I_1 = |G*_n|/|G*_1| measure the nonlinearity (FT rheology),
// and the Chebyshev coefficients of the elastic and viscous stresses,
//     σ′ = γ0 Σ e_n T_n(γ/γ0),   σ″ = γ̇0 Σ v_n T_n(γ̇/γ̇0),
// are e_n = G′_n (−1)^{(n−1)/2} and v_n = G″_n/ω: e3 > 0 is strain
// stiffening within a cycle, e3 < 0 softening; v3 > 0 shear thickening,
// v3 < 0 thinning. Units: G and e in E*; v in η_s (G″_n/E* over ω̃ = ωη_s/E*).
// The elastic and viscous parts of the stress (σ^e, σ^v, and the films' σ^film
// ⊆ σ^v) get their own G′, G″; N1, N2 and Π are reported by their cycle means.
//
// The periodic state. A run starts from rest, so its first cycle is a start-up
// and is never used. The transient after it is removed by MSER (batch 1) on
// the cycles' |G*| (steady_state.h): the truncation that minimises the
// estimated variance of the mean of what is left, restricted to the first half
// of the cycles. What is left is periodic when it does not drift: the slope of
// a straight line through its |G*| is either statistically insignificant
// (|z| ≤ 3) or negligible (its change over the window below a tenth of the
// target error). Means and standard errors are over the periodic cycles,
// treated as independent: each cycle of a nonlinear run passes through the
// plastic events that decorrelate the glass, and below the yield strain the
// response is deterministic and the cycles identical.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "micro/analysis/steady_state.h"

namespace softglass::micro {

/// The Fourier coefficients of one period sampled at equally spaced phases:
/// `sine[n]` = s′_n and `cosine[n]` = s″_n for n = 0 … max_harmonic (index 0
/// holds 0; the mean is `mean`). Requires max_harmonic < samples/2.
struct FourierSeries {
  double mean = 0.0;
  std::vector<double> sine, cosine;
};
FourierSeries fourier_series(std::span<const double> period, int max_harmonic);

/// The names of the per-cycle observables (common/oscillation_columns.h):
/// storage, loss (G′, G″ of σ); storage_elastic, loss_elastic, storage_viscous,
/// loss_viscous, storage_film, loss_film (of σ^e, σ^v, σ^film); intensity_3,
/// intensity_5 (I3/I1, I5/I1); e1, e3, v1, v3; N1, N2, pressure (cycle means).
const std::vector<std::string>& oscillation_observable_names();

/// One cycle's samples of σ, σ^e, σ^v, σ^film (shear components), N1, N2 and Π.
struct CycleSamples {
  std::span<const double> sigma, elastic, viscous, film, n1, n2, pressure;
};

/// The observables of one cycle (oscillation_observable_names() order), for
/// amplitude γ0 and reduced frequency ω̃.
std::vector<double> cycle_response(const CycleSamples& cycle, double amplitude, double frequency);

/// The periodic state of a run over its cycles ([cycle][observable]).
struct PeriodicSummary {
  std::size_t cycles = 0;                       // analysed
  std::size_t transient_cycles = 0;             // dropped: the start-up cycle and MSER's truncation
  std::vector<ObservableEstimate> observables;  // over the periodic cycles
  double drift = 0.0;                           // |z| of the slope of |G*| over the periodic cycles
  double drift_change = 0.0;  // that slope's change over the window, relative to |G*|
  bool periodic = false;      // enough periodic cycles that do not drift

  const MeanEstimate& operator[](const std::string& name) const;
  /// |G*| = √(G′² + G″²) of the means.
  double complex_modulus() const;
  /// max(SE(G′), SE(G″)) / |G*|.
  double worst_relative_error() const;
};

/// Requires cycles of oscillation_observable_names().size() finite values.
/// `min_periodic_cycles` ≥ 2; `target_relative_error` sets what a negligible
/// drift is (see the header).
PeriodicSummary summarise_cycles(const std::vector<std::vector<double>>& cycles,
                                 std::size_t min_periodic_cycles, double target_relative_error);

}  // namespace softglass::micro
