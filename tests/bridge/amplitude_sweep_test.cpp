// The amplitude-sweep law (bridge/law/amplitude_sweep.h) and a material's
// amplitude sweep from it (bridge/material/amplitude_sweep_prediction.h), on
// synthetic oscillation tables whose G′ and G″ are power laws between the
// simulated amplitudes, so that the strains read off them are known exactly:
// G′ = 1 up to γ0 = 0.01 and ∝ 1/γ0 beyond (softening at 0.01/0.9), G″ = 0.2
// (crossover at 0.05), times E* at each volume fraction.
#include <gtest/gtest.h>

#include <cmath>

#include "bridge/io/oscillation_table.h"
#include "bridge/law/law.h"
#include "bridge/material/amplitude_sweep_prediction.h"
#include "bridge_test_support.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

const std::vector<double> kAmplitudes = {1e-4, 1e-3, 1e-2, 1e-1, 1.0};

double storage_at(double gamma0) {
  return gamma0 <= 0.01 ? 1.0 : 0.01 / gamma0;
}

// One row per (φ, γ0) at ω̃ = 1e-7; G scaled by `scale[φ]`.
OscillationTable synthetic_table(const std::vector<double>& phi, const std::vector<double>& scale,
                                 double frequency = 1e-7) {
  OscillationTable t;
  t.source = "synthetic.csv";
  for (std::size_t i = 0; i < phi.size(); ++i)
    for (double g : kAmplitudes)
      t.points.push_back({phi[i],
                          frequency,
                          g,
                          2,
                          {scale[i] * storage_at(g), 1e-4 * scale[i]},
                          {scale[i] * 0.2, 1e-4 * scale[i]},
                          {scale[i], 0.0},
                          0});
  return t;
}

TEST(AmplitudeSweepLaw, ReadsPlateauSofteningAndCrossoverOffTheSweep) {
  const AmplitudeSweepLaw a =
      make_amplitude_sweep_law(synthetic_table({0.8, 0.85}, {0.03, 0.05}), {});
  ASSERT_EQ(a.phi.size(), 2u);
  EXPECT_EQ(a.frequency, 1e-7);
  EXPECT_EQ(a.amplitudes, kAmplitudes);
  for (std::size_t i = 0; i < 2; ++i) {
    const double scale = i ? 0.05 : 0.03;
    EXPECT_DOUBLE_EQ(a.plateau_storage[i].value, scale);
    EXPECT_DOUBLE_EQ(a.plateau_loss[i].value, 0.2 * scale);
    EXPECT_NEAR(a.softening_strain[i].value, 0.01 / 0.9, 1e-12);
    EXPECT_NEAR(a.crossover_strain[i].value, 0.05, 1e-12);
    // δγ/γ = δ ln(G′/G″)/|d ln(G′/G″)/d ln γ0|, the slope −1 here, δ ln(G′/G″)
    // weighted between the bracketing amplitudes 0.01 and 0.1 (relative
    // errors 1e-4/G̃′ and 1e-4/0.2 at each).
    const double w = std::log(5.0) / std::log(10.0);
    const double at_a = std::hypot(1e-4, 5e-4), at_b = std::hypot(1e-3, 5e-4);
    EXPECT_NEAR(a.crossover_strain[i].error, 0.05 * std::hypot((1 - w) * at_a, w * at_b), 1e-12);
  }
  validate(a, "synthetic");
}

TEST(AmplitudeSweepLaw, RefusesAmbiguousOrIncompleteTables) {
  OscillationTable two = synthetic_table({0.8}, {0.03});
  const OscillationTable other = synthetic_table({0.8}, {0.03}, 1e-6);
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  expect_contains(
      [&] {
        try {
          make_amplitude_sweep_law(two, {});
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"several frequencies", "--oscillation-frequency"});
  EXPECT_EQ(make_amplitude_sweep_law(two, 1e-6).frequency, 1e-6);
  EXPECT_THROW(make_amplitude_sweep_law(two, 3e-6), InputError);
  OscillationTable ragged = synthetic_table({0.8, 0.85}, {0.03, 0.05});
  ragged.points.pop_back();
  EXPECT_THROW(make_amplitude_sweep_law(ragged, {}), InputError);
}

// Rows from runs that did not reach their periodic state, and moduli negative
// beyond their errors, are read with a warning naming the row (as the
// flow-curve fit does for its unconverged runs); clean rows give none.
TEST(AmplitudeSweepLaw, WarnsOfUnconvergedRunsAndNegativeModuli) {
  const std::string header =
      "phi [1],omega_tilde [1],gamma0 [1],packings [1],converged [1],storage [E*],"
      "storage_se [E*],loss [E*],loss_se [E*],G0 [E*],G0_se [E*]\n";
  const OscillationTable clean = read_oscillation_table(CsvTable::parse(
      header + "0.8,1e-7,0.001,2,2,0.03,1e-4,0.006,1e-4,0.03,1e-4\n"
               "0.8,1e-7,0.01,2,2,-1e-5,1e-4,0.006,1e-4,0.03,1e-4\n",
      "clean.csv"));
  EXPECT_TRUE(clean.warnings.empty()) << "a G' within its error of zero is no warning";
  const OscillationTable suspect = read_oscillation_table(CsvTable::parse(
      header + "0.8,1e-7,0.001,2,1,0.03,1e-4,0.006,1e-4,0.03,1e-4\n"
               "0.8,1e-7,0.01,2,2,0.02,1e-4,-0.004,1e-4,0.03,1e-4\n",
      "suspect.csv"));
  ASSERT_EQ(suspect.warnings.size(), 2u);
  expect_contains(suspect.warnings[0], {"line 2", "1 of 2 runs did not meet their stopping rule"});
  expect_contains(suspect.warnings[1], {"line 3", "G'' = -0.004", "negative beyond its error"});
}

Law law_with_sweep() {
  Law law;
  law.amplitude_sweep =
      make_amplitude_sweep_law(synthetic_table({0.8, 0.85, 0.9}, {0.03, 0.05, 0.08}), {});
  return law;
}

// SI units: G = E* G̃, ω = ω̃ E*/η_s; between volume fractions the moduli
// interpolate in logarithm (geometric mean half way); and E* from a measured
// plateau inverts the prediction exactly.
TEST(AmplitudeSweepPrediction, ScalesByTheContactModulusAndInvertsFromThePlateau) {
  const Law law = law_with_sweep();
  const AmplitudeSweepPrediction p = predict_amplitude_sweep(law, {0.85, 4000.0, 1e-3, false});
  EXPECT_DOUBLE_EQ(p.angular_frequency, 1e-7 * 4000.0 / 1e-3);
  EXPECT_NEAR(p.plateau_storage.value, 0.05 * 4000.0, 1e-9);
  EXPECT_NEAR(p.storage.back().value, 0.05 * 0.01 * 4000.0, 1e-9);
  EXPECT_NEAR(p.crossover_strain.value, 0.05, 1e-12);
  const AmplitudeSweepPrediction half = predict_amplitude_sweep(law, {0.825, 1.0, 1.0, false});
  EXPECT_NEAR(half.plateau_storage.value, std::sqrt(0.03 * 0.05), 1e-12);
  const MaterialValue e_star = contact_modulus_from_amplitude_sweep(law, 0.825, 143.0, false);
  EXPECT_NEAR(e_star.value, 143.0 / std::sqrt(0.03 * 0.05), 1e-9);
  EXPECT_THROW(predict_amplitude_sweep(law, {0.95, 4000.0, 1e-3, false}), InputError);
  EXPECT_THROW(predict_amplitude_sweep(Law{}, {0.85, 4000.0, 1e-3, false}), InputError);
}

}  // namespace
}  // namespace softglass::bridge
