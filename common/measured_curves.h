// Measured rheometer data (instrument exports): flow curves for `bridge
// rescale`, torques for `macro compare`, amplitude sweeps for `bridge
// amplitude-sweep`. One reader for all.
//
// Layouts read (the shapes of ../shared/data/rheometry/ and common exports),
// one file each in common/measured/ (layout.h), tried in the order of
// registered_layouts.h:
//   - paired: a header that labels pairs of columns ("0.68,,0.70,,..."), each
//     pair one curve (shear rate, stress), no units in the header; rows may be
//     shorter for some pairs (both cells empty);
//   - long: one row per point, columns recognised by name (case, spaces,
//     underscores and hyphens do not matter):
//         shear rate        "shear rate", "rate", "gamma dot"
//         stress            "stress", "shear stress"
//         N1                "N1", "first normal stress difference"
//         torque            "torque"
//         angular velocity  "angular velocity", "rotation rate", "angular speed", "omega"
//         normal force      "normal force", "axial force"
//         storage modulus   "storage modulus", "G'"
//         loss modulus      "loss modulus", "G''"
//         strain amplitude  "oscillation strain", "strain amplitude"
//         frequency         "angular frequency" (of an oscillation)
//         curve label       "sample", "sample id", "curve", "label" (optional: groups rows)
//     other columns (viscosity, time, temperature, ...) are ignored. Units come
//     in brackets, "Stress [Pa]", or as a last underscore-separated part,
//     "stress_Pa".
// Units: rates in 1/s (also s^-1, s-1, 1/min); stresses in Pa, kPa, MPa or
// mPa; torques in N.m, mN.m, µN.m, nN.m (also written Nm, N m, N·m); angular
// velocities in rad/s, rpm or 1/min; forces in N, mN or g (gram-force, as rheometers
// export "Axial force [g]"); moduli as stresses; strain amplitudes in % or 1;
// oscillation frequencies in rad/s or Hz (a cycle per second is 2π rad/s). Headers of rates and
// stresses without units take the `fallback` units (the command line's --rate-unit, --stress-unit);
// without those, and for every other quantity, they are refused. Reduced units
// (E*, 1) are refused: these are measured, dimensional data. Values must be
// finite and positive (N1 and normal force may take any sign); each curve
// needs 4 points.
//
// Instrument exports (measured_file.h) reach these readers as sections: one
// per step of a TA TRIOS export or interval of an Anton Paar RheoCompass
// export, the whole table for a plain or delimited file.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/csv_table.h"
#include "common/measured_file.h"

namespace softglass {

/// How the user asks for a measured file to be read: its export format
/// (measured_file.h; "auto" detects it) and the units of rate and stress
/// columns whose headers give none (--rate-unit, --stress-unit).
struct MeasuredReading {
  std::string format = "auto";
  std::string rate{}, stress{};  // empty: none given
};

/// The quantities a column may hold; values are stored in SI units (a strain
/// as a fraction, a frequency in rad/s).
enum class Measured {
  shear_rate,
  stress,
  N1,
  torque,
  angular_velocity,
  normal_force,
  storage_modulus,
  loss_modulus,
  strain_amplitude,
  angular_frequency
};

/// One measured curve, every recognised column of it (SI units), sorted by its
/// abscissa: the shear rate, or the angular velocity when there is no rate, or
/// the strain amplitude when there is neither (an amplitude sweep).
struct RheometerCurve {
  std::string label;
  std::map<Measured, std::vector<double>> values;

  bool has(Measured q) const { return values.contains(q); }
  /// The column of `q`; InputError naming the curve and the quantity when
  /// the file has none (callers check has() or curve_kind() first).
  const std::vector<double>& operator[](Measured q) const;
  std::size_t size() const { return values.begin()->second.size(); }
};

/// The name of a quantity in messages: "shear rate", "G′".
std::string quantity_name(Measured q);

/// Every curve of the file; InputError unless each has an abscissa (shear
/// rate, angular velocity or strain amplitude) and an ordinate (stress,
/// torque or storage modulus).
std::vector<RheometerCurve> read_rheometer_curves(const CsvTable& csv,
                                                  const MeasuredReading& fallback);

/// What a measured curve is, from its columns. Any pair of an abscissa and
/// an ordinate makes a curve, so a file of one kind reads as curves where
/// another is wanted: each reader says what the file looks like instead.
enum class CurveKind {
  flow_curve,       // shear rate or angular velocity, and stress or torque
  amplitude_sweep,  // strain amplitude, and G′ or G″
  other,            // a mixture: a rate against a modulus, a strain against a torque
};
CurveKind curve_kind(const RheometerCurve& curve);
/// "an amplitude sweep (strain amplitude and G′/G″ columns)", for messages.
std::string describe(CurveKind kind);

/// InputError unless every curve of the file `source` is of the kind
/// `expected`: "'F' is an amplitude sweep (strain amplitude and G′/G″
/// columns), not a flow curve (...)", then `advice` if any.
void require_curve_kind(const std::vector<RheometerCurve>& curves, CurveKind expected,
                        const std::string& source, const std::string& advice = "");

/// A flow curve: shear rate and stress (optional N1).
struct MeasuredCurve {
  std::string label;
  std::vector<double> shear_rate;         // [1/s], increasing
  std::vector<double> stress;             // [Pa]
  std::optional<std::vector<double>> N1;  // [Pa]
};

/// The flow curves of the file; InputError unless it has shear rate and stress.
std::vector<MeasuredCurve> read_measured_curves(const CsvTable& csv, const MeasuredReading& fallback);

/// The curves of an export of one or more sections. A section's curve is
/// labelled by the section's title when the section has no label column.
std::vector<RheometerCurve> read_rheometer_curves(const MeasuredFile& file,
                                                  const MeasuredReading& fallback);
/// The curves of `file` of kind `kind`. A file of several sections (an
/// instrument's procedure) may hold other tests beside them: those sections
/// are left out, and so is a flow-curve section at one shear rate (a
/// transient at constant rate, not a flow curve). InputError, with `advice`,
/// when no section is of that kind, or when a one-section file is of another.
std::vector<RheometerCurve> curves_of_kind(const MeasuredFile& file, const MeasuredReading& fallback,
                                           CurveKind kind, const std::string& advice = "");
/// The flow curves (shear rate and stress) of an export.
std::vector<MeasuredCurve> read_measured_curves(const MeasuredFile& file,
                                                const MeasuredReading& fallback);

/// A measured curve holds tens to hundreds of points, each costing the tools a
/// solve or a plotted symbol; a file with more than this is taken for
/// something else (a time series, a whole export).
inline constexpr std::size_t kMostMeasuredPoints = 10000;

/// An amplitude sweep: G′ and G″ against the strain amplitude, at a frequency.
struct MeasuredAmplitudeSweep {
  std::string label;
  std::vector<double> strain;               // amplitude γ0 [1], increasing
  std::vector<double> storage;              // G′ [Pa]
  std::vector<double> loss;                 // G″ [Pa]
  std::optional<double> angular_frequency;  // [rad/s], when the file gives one for all points
};

/// The amplitude sweeps of the file; InputError unless it has strain
/// amplitude, storage and loss modulus, or its frequency varies along a curve.
std::vector<MeasuredAmplitudeSweep> read_amplitude_sweeps(const CsvTable& csv);
/// The amplitude sweeps of an export (its amplitude-sweep sections).
std::vector<MeasuredAmplitudeSweep> read_amplitude_sweeps(const MeasuredFile& file);

/// SI factor of a rate unit (1/s → 1, 1/min → 1/60); InputError naming `what` otherwise.
double rate_factor(const std::string& units, const std::string& what);
/// SI factor of a stress unit (Pa → 1, kPa → 1e3, ...); InputError naming `what` otherwise.
double stress_factor(const std::string& units, const std::string& what);

}  // namespace softglass
