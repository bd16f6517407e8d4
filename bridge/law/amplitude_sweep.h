// The amplitude-sweep law of a law file: what `micro oscillate` measured at
// one reduced frequency ω̃, per volume fraction — G′ and G″ against the strain
// amplitude γ0, and the numbers a rheologist reads off such a sweep:
//
//   plateau     G′ and G″ at the smallest amplitude (the linear plateau a
//               rheometer reports; with the paper's film law G″ at small γ0
//               still grows like (ω̃/γ0)^½ and G′ falls with γ0, the law having
//               no linear limit, so the softening strain below can be the
//               films' rather than yielding; a film rest thickness gives the
//               plateau back: docs/oscillation.md);
//   softening   the γ0 where G′ falls to 0.9 of its plateau (the end of the
//               linear regime);
//   crossover   the γ0 where G′ = G″ (the yield strain of the amplitude sweep).
//
// Both strains are interpolated linearly in ln γ0 between the two amplitudes
// that bracket them (ln G′ against ln γ0; ln(G′/G″) against ln γ0), with
// errors from the moduli's standard errors through the local slope. A strain
// not reached within the sweep is 0 ("not reached").
#pragma once

#include <optional>
#include <vector>

#include "bridge/io/oscillation_table.h"

namespace softglass::bridge {

struct AmplitudeSweepLaw {
  double frequency = 0.0;                            // ω̃
  std::vector<double> phi;                           // increasing
  std::vector<double> amplitudes;                    // γ0, increasing, the same for every φ
  std::vector<std::vector<Estimate>> storage, loss;  // [φ][amplitude], E*
  std::vector<Estimate> plateau_storage, plateau_loss, softening_strain, crossover_strain;  // per φ
  // Per φ, the fewest packings of its rows (empty: not recorded). With one, the
  // scatter between packings is unknown: every error of that φ is NaN ("n/a").
  std::vector<double> packings;

  /// Whether the errors at volume fraction `i` cannot be estimated.
  bool one_packing(std::size_t i) const { return !packings.empty() && packings[i] < 2; }
};

/// Every error of volume fraction `i` made NaN: its rows are one packing's.
void mark_errors_unknown(AmplitudeSweepLaw& law, std::size_t i);

/// G′ at the end of the linear regime, as a fraction of its plateau.
inline constexpr double kSoftening = 0.9;

/// The first γ0 of `amplitudes` (increasing) where f, positive before,
/// reaches 0, linear in ln γ0 between the two bracketing amplitudes, with its
/// error δ ln γ0 = δf/|df/d ln γ0| from the independent errors of f at both
/// ends (`f_error`) and an error `common` to several values (shifting them
/// together; empty: none); {0, 0} when f never reaches 0 ("not reached").
Estimate first_crossing(const std::vector<double>& amplitudes, const std::vector<double>& f,
                        const std::vector<double>& f_error, const std::vector<double>& common = {});

/// The softening strain (G′ down to kSoftening of its value at the first
/// amplitude) and the crossover strain (G′ = G″) of a sweep, with errors from
/// the moduli's (0 errors: none).
struct SweepStrains {
  Estimate softening, crossover;
};
SweepStrains sweep_strains(const std::vector<double>& amplitudes,
                           const std::vector<Estimate>& storage, const std::vector<Estimate>& loss);

/// The law of `table` at frequency `frequency` (needed when the table holds
/// several; InputError naming them otherwise). Every φ must have the same
/// amplitudes, at least three.
AmplitudeSweepLaw make_amplitude_sweep_law(const OscillationTable& table,
                                           std::optional<double> frequency);

/// Checks a law read from a file (list lengths, order, signs); InputError
/// naming `source` and the entry.
void validate(const AmplitudeSweepLaw& law, const std::string& source);

}  // namespace softglass::bridge
