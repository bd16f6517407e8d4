// `bridge predict` (bridge/material/prediction.h) on the bundled law of the
// paper sweep: each mode against an identity it must satisfy — (a) at the
// simulated rates is the table, (b) is (a) at E* = G'/(G0/E*) with a wider
// band, (c) starts at the measured yield stress and, at the simulated yield
// strain, needs no rate rescaling, (d) recovers the E* of a curve made by (a)
// — and the refusals of inputs that fit no mode.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "bridge/app/law_file.h"
#include "bridge/material/prediction.h"
#include "bridge_test_support.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

const std::filesystem::path kLawFile =
    std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases" / "bridge_law_paper_sweep.prm";

struct Fixture {
  Law law = read_law_file(kLawFile);
  SimulatedCurves curves = read_simulated_curves(kLawFile, law);
};

constexpr double kViscosity = 1e-3;

PredictionInputs with_modulus(double e_star) {
  return {.phi = 0.8, .viscosity = kViscosity, .modulus = e_star};
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
  const Prediction b = predict(f.law, f.curves,
                               {.phi = 0.8, .viscosity = kViscosity, .plateau_modulus = g_prime},
                               rates);
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
  const Prediction c = predict(
      f.law, f.curves,
      {.phi = 0.8, .viscosity = kViscosity, .modulus = e_star, .yield_stress = tau_y},
      {1e-12, 1.0});
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
  const Prediction cg = predict(
      f.law, f.curves,
      {.phi = 0.8, .viscosity = kViscosity, .plateau_modulus = g_prime, .yield_stress = tau_y},
      {1.0});
  const Prediction same_e = predict(
      f.law, f.curves,
      {.phi = 0.8, .viscosity = kViscosity, .modulus = cg.modulus.value, .yield_stress = tau_y},
      {1.0});
  EXPECT_NEAR(stress(cg, 0) / stress(same_e, 0), 1.0, 1e-4);
}

TEST(Prediction, ModeDRecoversTheModulusOfACurveModeAMade) {
  const Fixture f;
  const double e_star = 2500.0;
  MeasuredCurve curve{.label = "made", .shear_rate = {}, .stress = {}, .N1 = std::nullopt};
  for (int i = 0; i < 12; ++i) curve.shear_rate.push_back(1e-2 * std::pow(10.0, i / 3.0));
  const Prediction a = predict(f.law, f.curves, with_modulus(e_star), curve.shear_rate);
  for (std::size_t i = 0; i < curve.shear_rate.size(); ++i) curve.stress.push_back(stress(a, i));
  const Prediction d =
      predict(f.law, f.curves, {.phi = 0.8, .viscosity = kViscosity, .measured_curve = curve},
              {1.0});
  EXPECT_EQ(d.mode, PredictionMode::fitted_modulus);
  EXPECT_NEAR(d.modulus.value / e_star, 1.0, 1e-7);
  EXPECT_LT(d.modulus.error() / e_star, 1e-6);  // a perfect fit leaves no error
}

// The material a mode writes (bridge material --tabulated) and the curve it
// predicts are one: predict at the material's rates gives its stresses, and
// in mode (c) its yield stress is the measured one.
TEST(Prediction, TheModesMaterialIsItsPrediction) {
  const Fixture f;
  for (const PredictionInputs& in :
       {PredictionInputs{.phi = 0.8, .viscosity = kViscosity, .modulus = 2500.0},
        PredictionInputs{.phi = 0.82, .viscosity = kViscosity, .plateau_modulus = 150.0,
                         .yield_stress = 12.0}}) {
    const PredictionScales scales = prediction_scales(f.law, f.curves, in);
    const TabulatedMaterial m = tabulated_material_in_mode(f.law, f.curves, in, scales);
    std::vector<double> rates;
    for (const TabulatedRow& row : m.rows) rates.push_back(row.rate);
    const Prediction p = predict(f.law, f.curves, in, rates);
    for (std::size_t i = 0; i < rates.size(); ++i)
      EXPECT_NEAR(stress(p, i) / m.rows[i].value[index(Quantity::sigma)]->value, 1.0, 1e-12)
          << mode_name(scales.mode) << " " << i;
    EXPECT_EQ(m.source, mode_name(scales.mode));
    if (in.yield_stress) EXPECT_NEAR(m.yield.value / *in.yield_stress, 1.0, 1e-14);
  }
}

TEST(Prediction, RefusesInputsThatFitNoMode) {
  const Fixture f;
  MeasuredCurve curve{.label = "c", .shear_rate = {1, 2, 3, 4}, .stress = {5, 6, 7, 8}};
  const auto refused = [&](const PredictionInputs& in, const std::string& words) {
    try {
      predict(f.law, f.curves, in, {1.0});
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused({.phi = 0.8, .viscosity = kViscosity}, "no E*");
  refused({.phi = 0.8, .viscosity = kViscosity, .yield_stress = 10.0}, "mode (c) needs");
  refused({.phi = 0.8, .viscosity = kViscosity, .modulus = 1e3, .measured_curve = curve},
          "mode (d) fits E*");
  refused({.phi = 0.8, .viscosity = kViscosity, .modulus = 1e3, .plateau_modulus = 100.0},
          "not both");
  refused({.phi = 0.95, .viscosity = kViscosity, .modulus = 1e3}, "outside the simulated range");
}

}  // namespace
}  // namespace softglass::bridge
