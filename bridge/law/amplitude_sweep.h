// The amplitude-sweep law of a law file: what `micro oscillate` measured at
// one reduced frequency ω̃, per volume fraction — G′ and G″ against the strain
// amplitude γ0, and the numbers a rheologist reads off such a sweep:
//
//   plateau     G′ and G″ at the smallest amplitude (the linear plateau a
//               rheometer reports; in this model G″ at small γ0 still grows
//               like (ω̃/γ0)^½, the EHD film law having no linear limit:
//               docs/oscillation.md);
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
};

/// The first γ0 of `amplitudes` (increasing) where f, positive before,
/// reaches 0, linear in ln γ0 between the two bracketing amplitudes, with its
/// error from the errors of f at both ends (δ ln γ0 = δf/|df/d ln γ0|);
/// {0, 0} when f never reaches 0 ("not reached").
Estimate first_crossing(const std::vector<double>& amplitudes, const std::vector<double>& f,
                        const std::vector<double>& f_error);

/// The law of `table` at frequency `frequency` (needed when the table holds
/// several; InputError naming them otherwise). Every φ must have the same
/// amplitudes, at least three.
AmplitudeSweepLaw make_amplitude_sweep_law(const OscillationTable& table,
                                           std::optional<double> frequency);

/// Checks a law read from a file (list lengths, order, signs); InputError
/// naming `source` and the entry.
void validate(const AmplitudeSweepLaw& law, const std::string& source);

}  // namespace softglass::bridge
