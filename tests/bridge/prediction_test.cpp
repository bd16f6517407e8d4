// `bridge predict` (bridge/material/prediction.h) on the bundled law of the
// paper sweep: each mode against an identity it must satisfy — (a) at the
// simulated rates is the table, (b) is (a) at E* = G'/(G0/E*) with a wider
// band, (c) starts at the measured yield stress and, at the simulated yield
// strain, needs no rate rescaling, (d) recovers the E* of a curve made by (a)
// — and the refusals of inputs that fit no mode.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "bridge/material/prediction.h"
#include "bridge_test_support.h"
#include "bundled_law.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

using Fixture = testing::BundledLaw;
const std::filesystem::path& kLawFile = testing::kBundledLaw;

constexpr double kViscosity = 1e-3;

// Inputs at φ and the water-like η_s; each test sets what its mode takes.
PredictionInputs at(double phi) {
  PredictionInputs in;
  in.phi = phi;
  in.viscosity = kViscosity;
  return in;
}

PredictionInputs with_modulus(double e_star) {
  PredictionInputs in = at(0.8);
  in.modulus = e_star;
  return in;
}

double stress(const Prediction& p, std::size_t i) {
  return p.points[i].value[index(Quantity::sigma)]->value;
}
double band(const Prediction& p, std::size_t i) {
  return p.points[i].value[index(Quantity::sigma)]->band;
}

TEST(Prediction, ModeANothingFittedIsTheTableAtItsRates) {
  const Fixture f;
  const double e_star = 2000.0;
  const TabulatedMaterial table =
      make_tabulated_material(f.law, f.curves, {0.8, e_star, kViscosity, false});
  std::vector<double> rates;
  for (const TabulatedRow& row : table.rows) rates.push_back(row.rate);
  const Prediction p = predict(f.law, f.curves, with_modulus(e_star), rates);
  EXPECT_EQ(p.mode, PredictionMode::nothing_fitted);
  for (std::size_t i = 0; i < rates.size(); ++i) {
    const MaterialValue& row = *table.rows[i].value[index(Quantity::sigma)];
    EXPECT_NEAR(stress(p, i) / row.value, 1.0, 1e-12) << i;
    EXPECT_NEAR(band(p, i) / row.error(), 1.0, 1e-9) << i;
    EXPECT_FALSE(p.points[i].extrapolated) << i;
  }
  const Prediction outside = predict(f.law, f.curves, with_modulus(e_star),
                                     {0.1 * rates.front(), 10.0 * rates.back()});
  EXPECT_TRUE(outside.points[0].extrapolated);
  EXPECT_TRUE(outside.points[1].extrapolated);
}

TEST(Prediction, ModeBIsModeAAtTheModulusOfGPrimeWithItsError) {
  const Fixture f;
  const double g_prime = 150.0;
  const MaterialValue e_star = contact_modulus_from_plateau(f.law, 0.8, g_prime, false);
  const std::vector<double> rates{0.01, 1.0, 100.0};
  PredictionInputs in = at(0.8);
  in.plateau_modulus = g_prime;
  const Prediction b = predict(f.law, f.curves, in, rates);
  const Prediction a = predict(f.law, f.curves, with_modulus(e_star.value), rates);
  EXPECT_EQ(b.mode, PredictionMode::plateau_modulus);
  EXPECT_NEAR(b.modulus.value / e_star.value, 1.0, 1e-14);
  for (std::size_t i = 0; i < rates.size(); ++i) {
    EXPECT_NEAR(stress(b, i) / stress(a, i), 1.0, 1e-12) << i;
    EXPECT_GT(band(b, i), band(a, i)) << i;  // G0's error moves every stress
  }
}

TEST(Prediction, ModeCStartsAtTheMeasuredYieldStress) {
  const Fixture f;
  const double tau_y = 20.0, e_star = 2000.0;
  PredictionInputs in = with_modulus(e_star);
  in.yield_stress = tau_y;
  const Prediction c = predict(f.law, f.curves, in, {1e-12, 1.0});
  EXPECT_EQ(c.mode, PredictionMode::yield_stress);
  EXPECT_NEAR(stress(c, 0) / tau_y, 1.0, 1e-4);
  // Shape from the simulations: τ/τ_y,m = σ̃/σ̃_y at the same γ̃ when no G' rescales it.
  const Prediction a = predict(f.law, f.curves, with_modulus(e_star), {1e-12, 1.0});
  EXPECT_NEAR(stress(c, 1) / tau_y, stress(a, 1) / stress(a, 0), 1e-4);
  // A measured yield strain equal to the simulated one rescales no rate: the
  // G' that gives E* must then be τ_y,m/γ_y with γ_y = σ̃_y/(G0/E*).
  const MaterialValue g0 = interpolate_value(f.law.phi, f.law.modulus, 0.8);
  const double sigma_y = stress(a, 0) / e_star;  // σ̃_y: (a) at rest, in units of E*
  const double g_prime = tau_y * g0.value / sigma_y;
  PredictionInputs with_g = at(0.8);
  with_g.plateau_modulus = g_prime;
  with_g.yield_stress = tau_y;
  const Prediction cg = predict(f.law, f.curves, with_g, {1.0});
  PredictionInputs same = with_modulus(cg.modulus.value);
  same.yield_stress = tau_y;
  const Prediction same_e = predict(f.law, f.curves, same, {1.0});
  EXPECT_NEAR(stress(cg, 0) / stress(same_e, 0), 1.0, 1e-4);
}

TEST(Prediction, ModeDRecoversTheModulusOfACurveModeAMade) {
  const Fixture f;
  const double e_star = 2500.0;
  MeasuredCurve curve{.label = "made", .shear_rate = {}, .stress = {}, .N1 = std::nullopt};
  for (int i = 0; i < 12; ++i) curve.shear_rate.push_back(1e-2 * std::pow(10.0, i / 3.0));
  const Prediction a = predict(f.law, f.curves, with_modulus(e_star), curve.shear_rate);
  for (std::size_t i = 0; i < curve.shear_rate.size(); ++i) curve.stress.push_back(stress(a, i));
  PredictionInputs fit = at(0.8);
  fit.measured_curve = curve;
  const Prediction d = predict(f.law, f.curves, fit, {1.0});
  EXPECT_EQ(d.mode, PredictionMode::fitted_modulus);
  EXPECT_NEAR(d.modulus.value / e_star, 1.0, 1e-7);
  EXPECT_LT(d.modulus.error() / e_star, 1e-6);  // a perfect fit leaves no error
}

// The material a mode writes (bridge material --tabulated) and the curve it
// predicts are one: predict at the material's rates gives its stresses, and
// in mode (c) its yield stress is the measured one.
TEST(Prediction, TheModesMaterialIsItsPrediction) {
  const Fixture f;
  PredictionInputs c = at(0.82);
  c.plateau_modulus = 150.0;
  c.yield_stress = 12.0;
  for (const PredictionInputs& in : {with_modulus(2500.0), c}) {
    const PredictionScales scales = prediction_scales(f.law, f.curves, in);
    const TabulatedMaterial m = tabulated_material_in_mode(f.law, f.curves, in, scales);
    std::vector<double> rates;
    for (const TabulatedRow& row : m.rows) rates.push_back(row.rate);
    const Prediction p = predict(f.law, f.curves, in, rates);
    for (std::size_t i = 0; i < rates.size(); ++i)
      EXPECT_NEAR(stress(p, i) / m.rows[i].value[index(Quantity::sigma)]->value, 1.0, 1e-12)
          << mode_name(scales.mode) << " " << i;
    EXPECT_EQ(m.source, mode_name(scales.mode));
    if (in.yield_stress) {
      EXPECT_NEAR(m.yield.value / *in.yield_stress, 1.0, 1e-14);
    }
  }
}

// The scoreboard's error beside the law (bridge_law_paper_sweep_model_error.csv)
// is stated per point by its branch: the plateau's median below 1.5 τ_y, the
// flowing branch's above; a mode the scoreboard has not measured gets none.
TEST(Prediction, StatesTheModelErrorOfItsModeByBranch) {
  const Fixture f;
  const std::optional<ModelError> error = read_model_error(kLawFile);
  ASSERT_TRUE(error.has_value());
  PredictionInputs in = with_modulus(2000.0);
  in.yield_stress = 10.0;
  in.model_error = error;
  const Prediction c = predict(f.law, f.curves, in, {1e-6, 1e3});
  const ModelErrorEntry& plateau = error->at({'c', "tabulated", "plateau"});
  const ModelErrorEntry& flowing = error->at({'c', "tabulated", "flowing"});
  EXPECT_NEAR(*c.points[0].model_error, plateau.median_abs_error * stress(c, 0), 1e-12);
  EXPECT_NEAR(*c.points[1].model_error, flowing.median_abs_error * stress(c, 1), 1e-12);
  PredictionInputs a = with_modulus(2000.0);
  a.model_error = error;
  EXPECT_FALSE(predict(f.law, f.curves, a, {1.0}).points[0].model_error.has_value());
}

TEST(Prediction, RefusesInputsThatFitNoMode) {
  const Fixture f;
  MeasuredCurve curve{.label = "c", .shear_rate = {1, 2, 3, 4}, .stress = {5, 6, 7, 8}, .N1 = {}};
  const auto refused = [&](const PredictionInputs& in, const std::string& words) {
    try {
      predict(f.law, f.curves, in, {1.0});
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(at(0.8), "no E*");
  PredictionInputs yield_only = at(0.8);
  yield_only.yield_stress = 10.0;
  refused(yield_only, "mode (c) needs");
  PredictionInputs fit_and_modulus = with_modulus(1e3);
  fit_and_modulus.measured_curve = curve;
  refused(fit_and_modulus, "mode (d) fits E*");
  PredictionInputs twice = with_modulus(1e3);
  twice.plateau_modulus = 100.0;
  refused(twice, "not both");
  PredictionInputs outside = with_modulus(1e3);
  outside.phi = 0.95;
  refused(outside, "outside the simulated range");
}

}  // namespace
}  // namespace softglass::bridge
