// Everything `bridge fit` estimates from one sweep, computed by one function so
// that the bootstrap can recompute all of it on every replicate.
//
// Per volume fraction φ_j:
//   - Herschel–Bulkley fits Q = Q_y + k_Q γ̃^m of σ, N1, N2 and f_m (those present);
//   - the yield strain γ_y = σ_y/G0 from the σ fit;
//   - the φ's own universal constant from its m = ½ law Q = a + c √γ̃:
//     c/G0 for σ and N1, −c/G0 for N2 (a check of universality, φ by φ);
//   - with structure data, the paper's force law f_m = f_y + k_f γ̃^½ (its
//     Fig. 3c; exponent fixed at ½, the free exponent being the HB fit's).
// Over all φ:
//   - the universal laws (fit/universal_law.h): k for σ, k′ for N1, k″ for N2,
//     with the yield values they imply per φ;
//   - the mean over φ of the σ exponents m (the paper's m = 0.50 ± 0.02).
// A fit that fails leaves NaN in its numbers; the caller decides what that means.
#pragma once

#include <fmt/format.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bridge/fit/herschel_bulkley.h"
#include "bridge/fit/universal_law.h"
#include "bridge/sweep/sweep.h"

namespace softglass::bridge {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The sign of a universal law's rate term: −1 for N2, which falls with the
/// rate, so that k, k′ and k″ are all positive (fit/universal_law.h).
inline double universal_sign(Quantity q) {
  return q == Quantity::N2 ? -1.0 : 1.0;
}

struct GroupFit {
  double phi = 0.0;
  double modulus = kNaN;                 // G0/E*
  PerQuantity<HbParameters> hb;          // per quantity present
  double yield_strain = kNaN;            // σ_y/G0 with the Herschel–Bulkley σ_y
  PerQuantity<double> own_k;             // sigma, N1, N2: this φ's own universal constant
  PerQuantity<double> universal_yield;   // sigma, N1, N2: the yield values of the universal fits
  double universal_yield_strain = kNaN;  // σ_y/G0 with the universal fit's σ_y
  std::optional<double> force_yield, force_slope;  // f_y and k_f of the m = ½ force law
};

struct SweepFit {
  std::vector<GroupFit> groups;
  PerQuantity<double> k;  // universal constants: sigma k, N1 k′, N2 k″
  double mean_exponent = kNaN;
};

/// Goodness of fit and Jacobian covariances of the original sweep's fits.
struct FitDiagnostics {
  std::vector<PerQuantity<HerschelBulkleyFit>> hb;  // per group
  PerQuantity<UniversalFit> universal;              // sigma, N1, N2
};

struct SweepFitOutcome {
  SweepFit fit;
  FitDiagnostics diagnostics;
};

SweepFitOutcome fit_sweep(const Sweep& sweep);

/// Calls f(name, value) on every number of `fit` in a fixed order: the flat
/// layout in which the bootstrap collects them. `Fit` is SweepFit or const SweepFit.
template <class Fit, class F>
void visit_scalars(Fit& fit, F&& f) {
  const char* hb_names[] = {"yield", "consistency", "exponent"};
  for (auto& g : fit.groups) {
    const std::string at = fmt::format("phi {:.4g} ", g.phi);
    f(at + "G0", g.modulus);
    for (Quantity q : kAllQuantities) {
      const std::string name = at + column_name(q) + " ";
      if (auto& hb = g.hb[index(q)]) {
        f(name + hb_names[0], hb->yield);
        f(name + hb_names[1], hb->consistency);
        f(name + hb_names[2], hb->exponent);
      }
      if (auto& own = g.own_k[index(q)]) f(name + "own k", *own);
      if (auto& yield = g.universal_yield[index(q)]) f(name + "universal yield", *yield);
    }
    if (auto& y = g.force_yield) f(at + "force law f_y", *y);
    if (auto& k = g.force_slope) f(at + "force law k_f", *k);
    f(at + "yield strain", g.yield_strain);
    f(at + "universal yield strain", g.universal_yield_strain);
  }
  for (Quantity q : kAllQuantities)
    if (auto& k = fit.k[index(q)]) f(std::string("k ") + column_name(q), *k);
  f("mean exponent", fit.mean_exponent);
}

}  // namespace softglass::bridge
