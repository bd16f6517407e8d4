// The flow-curve table of docs/flow-curve-format.md and its per-packing
// companion, read strictly.
//
// The table holds one row per state point (φ, γ̃) averaged over packings; the
// companion one row per run (φ, γ̃, packing seed). Both are in reduced units:
// stresses in E*, forces in E* R². Every column must carry its units in
// brackets and the units must be the documented ones, so that a table in
// pascals (or a mixture) is refused instead of being fitted as if reduced.
//
// A row with γ̃ = 0 is the quasi-static limit (athermal quasi-static shear, a
// sweep's AQS case): its σ is the dynamic yield stress. The readers accept it;
// the fits leave it out (sweep/sweep.h).
//
// Beyond the documented columns, the bridge reads the optional structure
// columns `f_m [E*R^2]` and `f_m_se [E*R^2]`: the elastic force at the radius of
// maximum accumulation (Fig. 3c of the paper), for the force law. `micro
// sweep` writes them into the table when its runs were analysed; structure
// obtained otherwise comes as a companion structure table (merge_structure).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/csv_table.h"

namespace softglass::bridge {

/// A value and its standard error (one standard deviation).
struct Estimate {
  double value = 0.0;
  double error = 0.0;
};

/// The observables the bridge fits, each against γ̃: shear stress, first and
/// second normal stress differences, and the force at maximum accumulation.
enum class Quantity : std::size_t { sigma, N1, N2, force };
inline constexpr std::size_t kQuantities = 4;
inline constexpr std::array<Quantity, kQuantities> kAllQuantities = {Quantity::sigma, Quantity::N1,
                                                                     Quantity::N2, Quantity::force};

/// Column name in the tables: "sigma", "N1", "N2", "f_m".
const char* column_name(Quantity q);
/// Units in the tables: "E*" or "E*R^2".
const char* reduced_units(Quantity q);
/// Optional quantities indexed by Quantity.
template <class T>
using PerQuantity = std::array<std::optional<T>, kQuantities>;
inline std::size_t index(Quantity q) {
  return static_cast<std::size_t>(q);
}
/// N1 and N2 may take either sign; σ is positive.
inline bool may_be_negative(Quantity q) {
  return q == Quantity::N1 || q == Quantity::N2;
}
/// f_m may be 0: the minimum of g_{2,-2} can lie beyond contact of two mean
/// spheres (r_m > 2R at low rates and φ), where no force acts.
inline bool may_be_zero(Quantity q) {
  return q == Quantity::force;
}

/// One state point of the table, averaged over its packings.
struct StatePoint {
  double phi = 0.0, gamma_tilde = 0.0;
  std::size_t packings = 0;
  std::optional<std::size_t> converged;  // runs that met their stopping rule (`converged [1]`)
  Estimate modulus;                      // G0/E*: mean and standard error over packings
  PerQuantity<Estimate> values;          // sigma always present
  std::size_t line = 0;                  // in the file, for messages
};

struct FlowCurveTable {
  std::string source;
  std::vector<std::string> comments;        // provenance lines before the header
  std::vector<StatePoint> points;           // file order
  std::array<bool, kQuantities> present{};  // which quantities the table has
};

/// One run of the per-packing companion.
struct PackingRun {
  double phi = 0.0, gamma_tilde = 0.0;
  std::uint64_t seed = 0;
  double modulus = 0.0;        // G0/E* of this packing
  PerQuantity<double> values;  // sigma always present
  std::size_t line = 0;
};

/// Reads and checks the flow-curve table: required columns, units, finite
/// values, φ in (0, 1), γ̃ >= 0, σ > 0, standard errors > 0, G0 > 0, whole
/// packing counts ≥ 1, converged counts (optional column) within 0 … packings,
/// no state point twice. InputError names file, line, column.
FlowCurveTable read_flow_curve_table(const CsvTable& csv);

/// Adds the force at maximum accumulation from a structure table: columns
/// `phi [1]`, `gamma_tilde [1]`, `f_m [E*R^2]`, `f_m_se [E*R^2]` (others, such
/// as `r_m [R]`, ignored), one row per state point of `table`. InputError when
/// `table` has f_m already, a row matches no state point, a state point has no
/// row or two, or a value breaks the table's rules.
void merge_structure(FlowCurveTable& table, const CsvTable& csv);

/// Reads and checks the per-packing companion (same rules, `seed [1]` instead
/// of `packings [1]`, no standard errors needed).
std::vector<PackingRun> read_packing_runs(const CsvTable& csv);

/// The shear rates a fit sees: γ̃ in [lowest, highest]. A simulated flow curve
/// is not exactly Herschel–Bulkley, so its exponent depends on the window; a
/// measured curve covers its own (γ̇ η_s/E* over the instrument's rates), and
/// the two compare only over the same one.
struct RateWindow {
  double lowest = 0.0;
  double highest = std::numeric_limits<double>::infinity();
  bool everything() const { return lowest <= 0.0 && std::isinf(highest); }
};

/// Drops the state points and runs outside `window`; the quasi-static rows
/// (γ̃ = 0, not fitted) stay. InputError if the window is empty or reversed.
void keep_rates(const RateWindow& window, FlowCurveTable& table, std::vector<PackingRun>& runs);

}  // namespace softglass::bridge
