// The wall slip law of a slip table (slip_table.h), in reduced units and in SI.
//
// Per volume fraction, the reduced power law
//
//     Ṽ γ̃_app = A σ̃_w^p,        i.e.   V_s η_s/(E* R) = A (σ_w/E*)^p,
//
// fitted as the straight line y = ln A + p x through x = ln σ̃_w, y = ln(Ṽ γ̃)
// by weighted least squares (fit/least_squares.h). Both coordinates carry
// errors, so a row's variance is the effective variance
//
//     v_i = (se_V/V)_i² + p² (se_σ/σ)_i² + τ²,
//
// and χ²(ln A, p) = Σ (y_i − ln A − p x_i)²/v_i is minimised with p inside
// the weights (the straight-line fit with errors in both coordinates). τ is a
// scatter about the law beyond the rows' own errors: 0 when χ²/dof ≤ 1 with
// τ = 0, otherwise the value that brings χ²/dof to 1 (Paule and Mandel 1982),
// so that the errors of ln A and p, the covariance (JᵀJ)⁻¹ at the minimum,
// rest on the rows' standard errors when they explain the scatter and on the
// scatter when they do not. The goodness of fit reported is that of the
// rows' own errors (τ = 0). Relative errors below 1e-8 (the table's eight
// digits) are raised to it.
//
// SI: V_s = Ṽ γ̃ E* R/η_s and σ_w = σ̃_w E* give V_s = β σ_w^p with
//
//     β = A R E*^(1−p)/η_s   [m/s/Pa^p],
//
// macro's `power-law` slip law (macro/material/slip_laws/power_law.cpp) with
// yield stress 0. β is proportional to R: the particle size is the one scale
// the slip law needs that the bulk law does not.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "bridge/fit/least_squares.h"
#include "bridge/io/flow_curve_table.h"
#include "bridge/slip/slip_table.h"

namespace softglass::bridge {

/// One row in reduced units: σ̃_w and Ṽ γ̃_app, with their standard errors.
struct SlipPoint {
  Estimate stress, velocity;
};

struct SlipLawFit {
  double phi = 0.0;
  Estimate log_coefficient;  // ln A
  Estimate exponent;         // p
  double correlation = 0.0;  // corr(ln A, p)
  GoodnessOfFit goodness;    // of the rows' own standard errors (τ = 0)
  double scatter = 0.0;      // τ, in ln(Ṽ γ̃): added to the errors when > 0
  std::size_t points = 0;
  double stress_min = 0.0, stress_max = 0.0;  // of the fitted rows [E*]
  /// The stress at which Ṽ γ̃ is best determined (the errors of ln A and p
  /// cancel), and the relative error of the law there.
  double pivot_stress() const;
  double pivot_error() const;
};

/// Fits the reduced law to `points` (at least 2 with different stresses;
/// InputError otherwise, NumericalError if the solve fails).
SlipLawFit fit_slip_law(const std::vector<SlipPoint>& points);

/// What was fitted at one volume fraction of a table, and what was left out.
struct SlipTableFit {
  SlipLawFit law;
  std::vector<const SlipRow*> rows;  // all rows at this φ, in the table's order
  std::vector<bool> fitted;          // per row: within the stress limit
  double stress_limit = 0.0;         // [E*]; infinite without one
};

/// Per volume fraction of the table (increasing), the law through its rows
/// with σ̃_w ≤ stress_limit(φ). InputError naming φ and the limit when fewer
/// than two rows remain.
std::vector<SlipTableFit> fit_slip_table(const SlipTable& table,
                                         const std::function<double(double)>& stress_limit);

/// The reduced law at φ: the fits' ln A and p interpolated linearly in φ
/// between the two neighbouring volume fractions (material/interpolation.h),
/// their errors propagated (statistical) and the interpolation's own.
struct SlipLawAt {
  double phi = 0.0;
  Estimate log_coefficient, exponent;
  double correlation = 0.0;
  double stress_min = 0.0, stress_max = 0.0;  // fitted range at the neighbours [E*]
  bool extrapolated = false;
  std::string placement;  // "at the simulated volume fraction 0.8", "between ...", ...
};

/// InputError when φ lies outside the table's volume fractions and
/// `extrapolate` is false. With one volume fraction, extrapolating keeps its law.
SlipLawAt slip_law_at(const std::vector<SlipTableFit>& fits, double phi, bool extrapolate);

/// β = A R E*^(1−p)/η_s [m/s/Pa^p]; InputError naming the value unless
/// E*, η_s and R are positive and finite.
double slip_coefficient_si(double coefficient, double exponent, double modulus, double viscosity,
                           double radius);

/// The relative error of β from those of ln A and p and their correlation
/// (d ln β = d ln A − ln E* dp).
double slip_coefficient_relative_error(const SlipLawAt& law, double modulus);

/// macro's `subsection slip` (power-law, yield stress 0) with `comments` as
/// `#` lines above it: a fragment scene files include.
std::string slip_law_text(const std::vector<std::string>& comments, double coefficient,
                          double exponent);

}  // namespace softglass::bridge
