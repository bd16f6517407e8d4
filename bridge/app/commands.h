// The `bridge` subcommands, start to finish.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bridge/rescale/rescale.h"
#include "common/measured_curves.h"

namespace CLI {
class App;
}

namespace softglass::bridge {

struct FitOptions {
  std::filesystem::path table, packings;  // packings: the per-packing companion (optional)
  std::filesystem::path law;          // instead of `table`: a law file to add an amplitude sweep to
  std::filesystem::path structure;    // companion structure table with f_m (optional)
  std::filesystem::path oscillation;  // amplitude sweeps of `micro oscillate` (optional)
  std::optional<double> oscillation_frequency;  // which of its frequencies (ω̃)
  RateWindow rates;                             // the state points fitted (γ̃ = 0 rows kept)
  std::filesystem::path output = "law.prm";
  std::size_t replicates = 1000;
  std::uint64_t seed = 1;
  bool force = false, quiet = false;
};

/// Fits a flow-curve table; writes the law file and its CSV tables
/// (<stem>_phi.csv, <stem>_points.csv, <stem>_constants.csv) beside it. With
/// `law` instead of a table, that law file's flow laws are kept as they are
/// (its header too) and the amplitude-sweep law of `oscillation` is added:
/// only the law file is written.
void fit_command(const FitOptions& options, const std::string& command_line);

/// Where a material's E* comes from: one of these.
struct ModulusSource {
  std::optional<double> modulus;                      // E* [Pa], or
  std::optional<double> interfacial_tension, radius;  // γ_i [N/m] and R [m]: E* = 9.92 γ_i/R, or
  std::optional<double> plateau_modulus;              // a measured G′ plateau [Pa] (see below)
  /// Matched to the law's static G0 ("static", the flow-curve route) or to the
  /// plateau of its amplitude sweep ("amplitude-sweep").
  std::string plateau_source = "static";
};

/// What modes (c) and (d) of bridge/material/prediction.h take besides E*:
/// a measured yield stress, or a measured flow curve to fit E* to.
struct ModeInputs {
  std::optional<double> yield_stress;  // mode (c) [Pa]
  std::filesystem::path fit_to;        // mode (d): the measured flow curve
  std::string fit_curve;               // its label, when the file holds several
  MeasuredReading units;                 // of its columns without units
};

struct MaterialOptions {
  std::filesystem::path law, output;  // output empty: standard output
  double phi = 0.0, viscosity = 0.0;
  ModulusSource source;
  /// The angular frequency [rad/s] the user's amplitude sweep is at: set
  /// against the one the law's holds at for this E* and η_s (ω̃ E*/η_s).
  std::optional<double> frequency;
  bool extrapolate = false, force = false;
  /// The simulated flow curve itself (tabulated_material.h) instead of the
  /// Herschel–Bulkley summary; then also modes (c) and (d) of prediction.h.
  bool tabulated = false;
  ModeInputs mode;
};

/// Writes the material fragment for (φ, E*, η_s) from a law file. With a
/// measured G′ plateau, E* = G′/(G0/E*)(φ) from the law's static G0, or
/// G′/(G′ plateau/E*)(φ) from its amplitude sweep (plateau_source).
void material_command(const MaterialOptions& options, const std::string& command_line);

struct PredictOptions {
  std::filesystem::path law, output;  // output empty: standard output
  double phi = 0.0, viscosity = 0.0;
  ModulusSource source;  // plateau_source stays "static": predict uses the law's G0
  ModeInputs mode;
  std::string rates;  // a list of numbers, or a measured file
  std::string curve;  // the label of the rates' curve
  std::string form = "tabulated";  // or herschel-bulkley: the summary
  bool extrapolate = false, force = false;
};

/// The curve called `label` of a measured flow-curve file, or its only one;
/// InputError naming the labels otherwise.
MeasuredCurve measured_curve(const std::filesystem::path& file, const std::string& label,
                             const MeasuredReading& units);

/// Declares `bridge predict` and its options on `app`.
CLI::App* add_predict_command(CLI::App& app, PredictOptions& options);

/// Writes the predicted flow curve (bridge/material/prediction.h) at the
/// requested rates.
void predict_command(const PredictOptions& options, const std::string& command_line);

struct AmplitudeSweepOptions {
  std::filesystem::path law, data;                   // data: a measured amplitude sweep (optional)
  std::filesystem::path output = "amplitude_sweep";  // folder
  double phi = 0.0, viscosity = 0.0;
  ModulusSource source;
  std::string sample;           // the curve of `data` when it holds several
  std::string format = "auto";  // the export format of `data` (common/measured_file.h)
  bool extrapolate = false, force = false;
};

/// The material's amplitude sweep (G′, G″ against γ0, in Pa) from the law's;
/// with measured data, the two compared point by point (errors per point and
/// per branch, the crossover strains, an overlay plot).
void amplitude_sweep_command(const AmplitudeSweepOptions& options, const std::string& command_line);

struct SlipLawOptions {
  std::filesystem::path table, output;  // output empty: standard output
  std::filesystem::path below_yield;    // a law file: fit only rows below its yield stress
  std::optional<double> max_stress;     // fit only rows with sigma_w <= this [E*]
  std::optional<double> phi;            // the volume fraction of the SI law
  // SI: all three or none.
  std::optional<double> modulus, viscosity, radius;
  bool extrapolate = false, force = false;
};

/// Fits the wall slip law Ṽ γ̃ = A σ̃_w^p of a `micro slip` table per volume
/// fraction (bridge/slip/slip_law.h) and, with E*, η_s and R, writes the
/// macro `subsection slip` (power-law, β = A R E*^(1−p)/η_s) at φ.
void slip_law_command(const SlipLawOptions& options, const std::string& command_line);

struct RescaleOptions {
  std::filesystem::path data, law;  // law empty: the paper's constants
  std::filesystem::path output = "rescaled.csv";
  RescaleSettings settings;
  MeasuredReading units;
  // γ_y of each curve from the law file at its φ (given, or from the labels).
  std::vector<double> phi;
  bool phi_from_labels = false, extrapolate = false;
  bool force = false;
};

/// Rescales measured curves onto the universal law; writes the points table and
/// <stem>_curves.csv beside it.
void rescale_command(const RescaleOptions& options, const std::string& command_line);

}  // namespace softglass::bridge
