// The oscillation table of `micro oscillate` (docs/oscillation.md), read
// strictly: one row per (φ, ω̃, γ0) averaged over packings, moduli in E*.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "bridge/io/flow_curve_table.h"
#include "common/csv_table.h"

namespace softglass::bridge {

struct OscillationPoint {
  double phi = 0.0, frequency = 0.0, amplitude = 0.0;  // φ, ω̃, γ0
  std::size_t packings = 0;
  Estimate storage, loss;  // G′, G″ of σ (E*)
  Estimate modulus;        // static G0 of the packings (E*)
  std::size_t line = 0;
};

struct OscillationTable {
  std::string source;
  std::vector<std::string> comments;
  std::vector<OscillationPoint> points;  // file order
  std::vector<std::string> warnings;     // rows read but not to be trusted blindly
};

/// Reads and checks the table: required columns and units, finite values, φ in
/// (0, 1), ω̃ and γ0 > 0, standard errors ≥ 0, G0 > 0, packings ≥ 1, no point
/// twice. InputError names file, line, column. A row is kept with a warning
/// when some of its runs did not meet their stopping rule (column `converged`)
/// or when G′ or G″ is negative beyond twice its standard error: a material
/// that stores or dissipates negative work is no steady oscillation.
OscillationTable read_oscillation_table(const CsvTable& csv);

}  // namespace softglass::bridge
