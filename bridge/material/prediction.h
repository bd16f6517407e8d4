// `bridge predict`: the flow curve σ(γ̇), N1(γ̇), N2(γ̇) of a material at the
// rates a user asks for, in SI units, each with its band — what a rheologist
// overlays on their own data — from the simulated flow curve (the tabulated
// law of tabulated_material.h, evaluated by the very law macro runs,
// macro/material/tabulated_law.h) and what the user knows of the material.
//
// Four modes, after what is known (the paper validated its law in two of them,
// Seth et al. 2011, Fig. 5):
//   (a) nothing fitted: E*, η_s, φ (E* given, or 9.92 γ_i/R for emulsions);
//       τ(γ̇) = E* σ̃(γ̃), γ̃ = γ̇ η_s/E*.
//   (b) E* from a measured linear modulus G′: E* = G′/(G0/E*)(φ), then (a).
//   (c) a measured yield stress τ_y,m (the paper's emulsion route): the model
//       supplies the shape, the measurement the scale,
//           τ(γ̇) = τ_y,m σ̃(γ̃ s)/σ̃_y,   s = (γ_y/γ_y,m)²,
//       σ̃_y the simulated quasi-static yield stress. With G′ also measured the
//       rates are rescaled by the yield strains (the universal law's variable
//       is γ̃/γ_y²; γ_y,m = τ_y,m/G′, γ_y = σ̃_y/(G0/E*)); with E* alone s = 1.
//   (d) E* fitted to one measured flow curve (the paper's microgel route):
//       the E* minimising Σ (ln τ(γ̇_i) − ln τ_i)², then (a) at any rate, φ or η_s.
//
// Bands (one standard deviation), in quadrature:
//   - statistical: the packings' error of each simulated point (propagated by
//     the interpolation in φ, not a single packing's standard error);
//   - interpolation: between simulated φ (tabulated_material.h);
//   - the scale: E*'s error (b: G0's; d: the fit's) moves τ by (1 − s) δE*/E*,
//     s = d ln τ/d ln γ̇, since E* scales stresses and divides rates;
//     (c): σ̃_y's statistical error.
// The Herschel–Bulkley summary (LawForm) uses the same bands: its own misfit
// is what the scoreboard shows beside the tabulated law's.
// Between rates the bands are interpolated linearly in ln γ̇; outside the
// simulated window the law is extrapolated (flagged per point) and the band is
// that of the nearest end. The model's own systematic error for each mode is
// not part of the band: the scoreboard measures it against public data
// (model_error.h), and the prediction states it beside the band, in its own
// column, with the data sets it comes from.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bridge/law/law.h"
#include "bridge/material/model_error.h"
#include "bridge/material/tabulated_material.h"
#include "common/measured_curves.h"

namespace softglass::bridge {

/// The law evaluated: the simulated curve itself, or its Herschel–Bulkley
/// summary (to set the two side by side; the bands are the simulated points'
/// in both).
enum class LawForm { tabulated, herschel_bulkley };

enum class PredictionMode { nothing_fitted, plateau_modulus, yield_stress, fitted_modulus };

/// "(a) nothing fitted", …: how the mode is named in every output.
std::string mode_name(PredictionMode mode);

struct PredictionInputs {
  double phi = 0.0, viscosity = 0.0;           // φ, η_s [Pa s]
  std::optional<double> modulus;               // E* [Pa] (a; c)
  std::optional<double> plateau_modulus;       // G′ [Pa] (b; c)
  std::optional<double> yield_stress;          // τ_y,m [Pa] (c)
  std::optional<MeasuredCurve> measured_curve;  // the curve E* is fitted to (d)
  bool extrapolate = false;                    // φ outside the simulated range
  LawForm form = LawForm::tabulated;
  std::optional<ModelError> model_error;       // the scoreboard's, beside the law (model_error.h)
};

/// The mode the inputs call for; InputError naming what is missing or what
/// does not belong (E* given beside a curve to fit it to, …).
PredictionMode prediction_mode(const PredictionInputs& inputs);

/// What a mode makes of its inputs: the E* that sets the rates, the stress
/// scale (E*, or τ_y,m/σ̃_y in mode c) with its relative error, the factor s
/// on γ̃ (mode c with G′), and the notes stating them.
struct PredictionScales {
  PredictionMode mode = PredictionMode::nothing_fitted;
  MaterialValue modulus;  // E* [Pa]
  double stress_scale = 0.0, stress_scale_error = 0.0, rate_factor = 1.0;
  std::vector<std::string> notes;
};

PredictionScales prediction_scales(const Law& law, const SimulatedCurves& curves,
                                   const PredictionInputs& inputs);

struct Band {
  double value = 0.0, band = 0.0;  // [Pa]
};

struct PredictedPoint {
  double rate = 0.0;         // γ̇ [1/s]
  PerQuantity<Band> value;   // sigma always, N1 and N2 when the law has them
  bool extrapolated = false;  // outside the simulated rates
  /// The shear stress's systematic error for the mode [Pa] (model_error.h),
  /// when the scoreboard has measured it.
  std::optional<double> model_error;
};

struct Prediction {
  PredictionMode mode = PredictionMode::nothing_fitted;
  MaterialValue modulus;           // E* [Pa] used (c: the one that sets the rates)
  std::vector<std::string> notes;  // the mode's inputs and what the band holds
  std::vector<PredictedPoint> points;
};

/// The prediction at `rates` (> 0); InputError for inputs out of range.
Prediction predict(const Law& law, const SimulatedCurves& curves, const PredictionInputs& inputs,
                   const std::vector<double>& rates);

/// The tabulated material of the mode (tabulated_material.h): the simulated
/// rows at γ̇_i = γ̃_i E*/(η_s s) with stresses scale × σ̃_i, each band scaled
/// alike; in mode (c) the yield stress is the measured one.
TabulatedMaterial tabulated_material_in_mode(const Law& law, const SimulatedCurves& curves,
                                             const PredictionInputs& inputs,
                                             const PredictionScales& scales);

/// The CSV: shear rate [1/s] and shear stress [Pa] first, then N1, N2, each
/// quantity's band, the shear stress's model error (when measured) and the
/// extrapolation flag; `provenance` and the notes as
/// `#` lines before the header.
std::string prediction_table(const Prediction& prediction,
                             const std::vector<std::string>& provenance);

}  // namespace softglass::bridge
