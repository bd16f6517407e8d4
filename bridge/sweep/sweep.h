// A sweep: the flow-curve table grouped by volume fraction, the form the fits use.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bridge/fit/curve.h"
#include "bridge/io/flow_curve_table.h"

namespace softglass::bridge {

/// Every state point of one volume fraction.
struct PhiGroup {
  double phi = 0.0;
  Estimate modulus;           // G0/E* of the packings at this φ
  PerQuantity<Curve> curves;  // against γ̃, increasing, smoothed errors; sigma always
  PerQuantity<std::vector<double>> table_errors;  // the table's standard errors, unsmoothed
  std::vector<std::size_t> lines;                 // table line of each state point, in γ̃ order
  std::vector<std::size_t> packings;              // packings averaged at each state point
  /// The quasi-static row (γ̃ = 0) of this φ, if the table has one: its σ is
  /// the AQS yield stress, a check of the fitted σ_y. Not in the curves, whose
  /// fits take logarithms of γ̃, nor in G0.
  std::optional<StatePoint> quasi_static;
};

struct Sweep {
  std::vector<PhiGroup> groups;  // increasing φ
  std::array<bool, kQuantities> present{};
  /// State points averaging runs that did not meet their stopping rule
  /// (`converged` < `packings`), as "phi = 0.8, gamma~ = 1e-09: 3 of 5".
  std::vector<std::string> unconverged;
  std::size_t points() const;               // state points in the curves (γ̃ > 0)
  std::size_t quasi_static_points() const;  // γ̃ = 0 rows
};

/// Groups the table by φ (values within 1e-9 are one φ), sets its γ̃ = 0 row
/// apart (PhiGroup::quasi_static), sorts the other rows by γ̃,
/// smooths the standard errors along each curve (fit/error_model.h) and
/// combines the G0 of its rows: rows normally repeat the same G0 (the same
/// packings sheared at every rate); distinct values are averaged as independent
/// estimates. InputError when a φ has fewer than 4 shear rates (a
/// Herschel–Bulkley fit has 3 parameters and needs a degree of freedom).
Sweep make_sweep(const FlowCurveTable& table);

/// The index of the group holding φ, or groups.size().
std::size_t find_group(const Sweep& sweep, double phi);

}  // namespace softglass::bridge
