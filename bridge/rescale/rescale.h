// `bridge rescale`: measured flow curves placed on the universal curve (the
// paper's Fig. 5), with E* fitted when it cannot be measured (microgels).
//
// The universal law in SI units, with γ̃ = γ̇ η_s/E*:
//     τ/τ_y = 1 + k (γ̇ η_s / (E* γ_y²))^½.
// A curve is placed on it by its yield stress τ_y, its yield strain γ_y and E*:
//   - E*, η_s and γ_y given: τ_y is fitted (or given too);
//   - E* unknown: E* is fitted with τ_y. Only E* γ_y² enters, so γ_y must be
//     given — directly, or through the measured shear modulus G0 as the paper
//     does (γ_y = τ_y/G0), and then τ = τ_y + k G0 (γ̇ η_s/E*)^½.
// Fits minimise the relative residuals (τ_i − τ_model,i)/τ_i — constant
// relative errors, the usual case for rheometer data, with no weights to
// guess — over the points inside the rate window; parameters are fitted in
// logarithm (they are positive) and their errors come from the Jacobian scaled
// by the residual variance χ²/dof. The N1 law N1/τ_y = N1_y/τ_y + k′ (…)^½
// (fit/universal_law.h) then fixes the plateau N1_y, of either sign, by least
// squares with residuals (N1 − model)/τ_y over the same window. Every curve
// also gets its own Herschel–Bulkley fit τ = τ_y + K γ̇^n with the same weights;
// a curve whose τ_y is to be fitted must show its yield plateau
// (fit/herschel_bulkley.h).
//
// One E* for several curves (`shared_modulus`): the same particles measured at
// several φ or temperatures have one contact modulus. E* is then the minimum of
// the profile S(E*) = Σ_curves χ²_j(E*), each curve's τ_y refitted at every trial
// E* (Brent's method on ln E*, bracketed by the curves' own E* fits), and its
// error is var ln E* = 2 s² / S″ with s² = S/(points − fitted parameters): the
// curvature of the profile is that of the joint χ², so the error includes the
// curves' τ_y uncertainties. The curves' τ_y errors are then those at the
// fitted E* (conditional on it).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bridge/fit/herschel_bulkley.h"
#include "bridge/io/flow_curve_table.h"
#include "bridge/law/law.h"
#include "common/measured_curves.h"

namespace softglass::bridge {

struct RescaleSettings {
  double viscosity = 0.0;             // η_s [Pa s]
  std::optional<double> modulus;      // E* [Pa]; fitted when absent
  std::vector<double> yield_strain;   // γ_y: one value for all curves, or one per curve
  std::vector<double> shear_modulus;  // G0 [Pa], instead of γ_y: one, or one per curve
  std::vector<double> yield_stress;   // τ_y [Pa]: fitted when empty; one, or one per curve
  double k = PaperValues::k.value, k_N1 = PaperValues::k_N1.value;
  double min_rate = 0.0, max_rate = std::numeric_limits<double>::infinity();  // [1/s]
  bool shared_modulus = false;  // one fitted E* for all curves
};

struct RescaledCurve {
  std::string label;
  HerschelBulkleyFit herschel_bulkley;  // of the measured curve; covariance scaled by χ²/dof
  Estimate yield_stress, modulus, yield_strain;  // error 0 when given
  bool yield_stress_fitted = false, modulus_fitted = false;
  bool modulus_shared = false;  // E* fitted once for all curves
  std::optional<Estimate> N1_yield;
  // Per point, all points (used[i]: inside the rate window, in the fits):
  std::vector<double> collapse_rate;                         // γ̇ η_s / (E* γ_y²)
  std::vector<double> stress_ratio;                          // τ/τ_y
  std::vector<double> residual;                              // (τ − model)/τ
  std::optional<std::vector<double>> N1_ratio, N1_residual;  // N1/τ_y, (N1 − model)/τ_y
  std::vector<bool> used;
  double rms_residual = 0.0;  // over the used points
  double chi2 = 0.0;  // Σ ((τ − model)/τ)² over the used points: what the fit minimises
  std::optional<double> N1_rms_residual;
};

/// InputError for settings that do not fit the curves (lists of the wrong
/// length, neither γ_y nor G0, non-positive values, fewer than 4 points in the
/// window, no yield plateau where τ_y is fitted); NumericalError when a fit fails.
std::vector<RescaledCurve> rescale(const std::vector<MeasuredCurve>& curves,
                                   const RescaleSettings& settings);

}  // namespace softglass::bridge
