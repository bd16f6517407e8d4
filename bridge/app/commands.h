// The `bridge` subcommands, start to finish.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bridge/rescale/rescale.h"
#include "common/measured_curves.h"

namespace softglass::bridge {

struct FitOptions {
  std::filesystem::path table, packings;  // packings: the per-packing companion (optional)
  std::filesystem::path structure;        // companion structure table with f_m (optional)
  std::filesystem::path output = "law.prm";
  std::size_t replicates = 1000;
  std::uint64_t seed = 1;
  bool force = false, quiet = false;
};

/// Fits a flow-curve table; writes the law file and its CSV tables
/// (<stem>_phi.csv, <stem>_points.csv, <stem>_constants.csv) beside it.
void fit_command(const FitOptions& options, const std::string& command_line);

struct MaterialOptions {
  std::filesystem::path law, output;  // output empty: standard output
  double phi = 0.0, viscosity = 0.0;
  std::optional<double> modulus;                      // E* [Pa], or
  std::optional<double> interfacial_tension, radius;  // γ_i [N/m] and R [m]: E* = 9.92 γ_i/R
  std::optional<double> plateau_modulus;              // G' [Pa]: E* = G'/(G0/E*)(phi) from the law
  bool extrapolate = false, force = false;
};

/// Writes the material fragment for (φ, E*, η_s) from a law file.
void material_command(const MaterialOptions& options, const std::string& command_line);

struct RescaleOptions {
  std::filesystem::path data, law;  // law empty: the paper's constants
  std::filesystem::path output = "rescaled.csv";
  RescaleSettings settings;
  FallbackUnits units;
  // γ_y of each curve from the law file at its φ (given, or from the labels).
  std::vector<double> phi;
  bool phi_from_labels = false, extrapolate = false;
  bool force = false;
};

/// Rescales measured curves onto the universal law; writes the points table and
/// <stem>_curves.csv beside it.
void rescale_command(const RescaleOptions& options, const std::string& command_line);

}  // namespace softglass::bridge
