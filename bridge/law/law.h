// The law file: what `bridge fit` learned from a sweep, in the form `bridge
// material` and people read it — a .prm fragment in deal.II ParameterHandler
// syntax (`subsection law … end`), reduced units, every number with its
// standard error, the provenance in comments.
//
// Per volume fraction: G0/E*, the yield strain, and for σ (always), N1, N2 and
// f_m (when the sweep had them) the Herschel–Bulkley yield value, consistency
// and exponent, with the correlation of ln|consistency| and the exponent (the
// consistency is the value at γ̃ = 1, far outside the data, so its error is
// mostly the exponent's; the correlation lets `material` propagate both into
// K = E* k (η_s/E*)^m without counting that error twice).
// With structure data, also the force law f_m = f_y + k_f γ̃^½ per volume
// fraction (in subsection f_m, beside the free-exponent fit). With an
// oscillation table, the amplitude-sweep law (law/amplitude_sweep.h) in
// subsection `amplitude sweep`.
// Over all volume fractions: the universal constants k, k′, k″ and the mean
// exponent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bridge/io/flow_curve_table.h"
#include "bridge/law/amplitude_sweep.h"
#include "bridge/sweep/analysis.h"

namespace softglass::bridge {

struct HbLaw {
  std::vector<Estimate> yield, consistency, exponent;  // per volume fraction
  std::vector<double> correlation;                     // corr(ln|consistency|, exponent)
};

/// f_m = f_y + k_f γ̃^½, in E* R², per volume fraction.
struct ForceLaw {
  std::vector<Estimate> yield, slope;
};

struct Law {
  std::vector<double> phi;  // increasing
  double gamma_tilde_min = 0.0, gamma_tilde_max = 0.0;
  std::vector<Estimate> modulus, yield_strain;  // per volume fraction
  // Per volume fraction, the fewest packings any of its state points averages;
  // empty for a law written before it was recorded. With one packing G0 has no
  // packing-to-packing scatter to estimate: its error is NaN ("n/a").
  std::vector<double> packings;
  PerQuantity<HbLaw> hb;                        // sigma always
  std::optional<ForceLaw> force;                // with structure data
  PerQuantity<Estimate> k;                      // sigma: k, N1: k′, N2: k″
  Estimate mean_exponent;
  std::optional<AmplitudeSweepLaw> amplitude_sweep;  // from `micro oscillate`
  std::vector<std::string> provenance;               // comment lines, without '#'
};

/// The law of an analysed sweep; `provenance` becomes its header comments.
Law make_law(const SweepAnalysis& analysis, std::vector<std::string> provenance);

/// The law as a .prm fragment.
std::string law_text(const Law& law);

/// Checks a law read from a file (list lengths, signs, ranges); InputError
/// naming `source` and the entry.
void validate(const Law& law, const std::string& source);

/// The paper's values (Seth et al. 2011), for comparison and as the constants
/// of `bridge rescale` without a law file.
struct PaperValues {
  static constexpr Estimate k{80.0, 3.0}, k_N1{20.0, 2.0}, k_N2{26.0, 2.0};
  static constexpr Estimate exponent{0.50, 0.02};
  static constexpr double yield_strain_min = 0.02, yield_strain_max = 0.04;
};

/// A result file beside `main`: law.prm → law_phi.csv, the naming of the
/// tables `bridge fit` writes beside its law file (and of other results).
std::filesystem::path beside(const std::filesystem::path& main, const std::string& suffix);

/// The name of an entry list in the law file for one quantity: "sigma", "N1", "N2", "f_m".
inline const char* law_subsection(Quantity q) {
  return column_name(q);
}

}  // namespace softglass::bridge
