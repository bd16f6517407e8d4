// Measured flow curves (rheometer exports) for `bridge rescale`.
//
// Layouts read (the shapes of ../shared/data/rheometry/ and common exports):
//   - long: one row per point, columns recognised by name (case, spaces,
//     underscores and hyphens do not matter):
//         shear rate   "shear rate", "rate", "gamma dot"
//         stress       "stress", "shear stress"
//         N1           "N1", "first normal stress difference"
//         curve label  "sample", "sample id", "curve", "label" (optional: groups rows)
//     other columns (viscosity, torque, time, ...) are ignored. Units come in
//     brackets, "Stress [Pa]", or as a last underscore-separated part,
//     "stress_Pa";
//   - paired: a header that labels pairs of columns ("0.68,,0.70,,..."), each
//     pair one curve (shear rate, stress), no units in the header; rows may be
//     shorter for some pairs (both cells empty).
// Units: rates in 1/s (also s^-1, s-1, 1/min); stresses in Pa, kPa, MPa or mPa.
// Headers without units take the `fallback` units (the command line's
// --rate-unit, --stress-unit); without those they are refused. Reduced units
// (E*, 1) are refused: these are measured, dimensional curves. Values must be
// finite and positive (N1 may take any sign); each curve needs 4 points.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bridge/io/csv_table.h"

namespace softglass::bridge {

struct MeasuredCurve {
  std::string label;
  std::vector<double> shear_rate;         // [1/s], increasing
  std::vector<double> stress;             // [Pa]
  std::optional<std::vector<double>> N1;  // [Pa]
};

struct FallbackUnits {
  std::string rate, stress;  // empty: none given
};

std::vector<MeasuredCurve> read_measured_curves(const CsvTable& csv, const FallbackUnits& fallback);

/// SI factor of a rate unit (1/s → 1, 1/min → 1/60); InputError naming `what` otherwise.
double rate_factor(const std::string& units, const std::string& what);
/// SI factor of a stress unit (Pa → 1, kPa → 1e3, ...); InputError naming `what` otherwise.
double stress_factor(const std::string& units, const std::string& what);

}  // namespace softglass::bridge
