// The table of `micro slip` (docs/physics.md, "Wall slip"): particles sheared
// between two smooth walls, one row per volume fraction, apparent rate and
// packing, with the wall shear stress and the slip velocity it measured.
//
// Reduced units: σ̃_w = σ_w/E*, the slip velocity Ṽ in units of γ̇_app R with
// γ̇_app = γ̃_app E*/η_s, so that Ṽ γ̃_app = V_s η_s/(E* R) does not depend on
// the rate. micro writes the columns without units; a column may carry them
// (`wall_stress [E*]`), and then they must be the documented ones.
//
// Read strictly, like every bridge input: the columns phi, gamma_app,
// wall_stress, wall_stress_se, slip_velocity, slip_velocity_se are required,
// every cell must be a finite number (CsvTable), φ in (0, 1), γ̃_app, σ̃_w and
// Ṽ > 0, standard errors ≥ 0. `converged` and `bulk_rate` (γ̇_bulk/γ̇_app)
// are used when present; other columns are ignored.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bridge/io/flow_curve_table.h"
#include "common/csv_table.h"

namespace softglass::bridge {

struct SlipRow {
  double phi = 0.0, gamma_app = 0.0;  // φ, γ̃_app
  Estimate wall_stress;               // σ̃_w [E*]
  Estimate slip_velocity;             // Ṽ [γ̇_app R]
  std::optional<double> bulk_rate;    // γ̇_bulk/γ̇_app: 0 for a sliding plug
  bool converged = true;              // the run met its stopping rule
  std::size_t line = 0;               // in the file, for messages
};

struct SlipTable {
  std::string source;
  std::vector<std::string> comments;
  std::vector<SlipRow> rows;
};

/// The rows of a slip table; InputError naming file, line and column.
SlipTable read_slip_table(const CsvTable& csv);

}  // namespace softglass::bridge
