// What a scene computes at one operating point, as named quantities in SI
// units: the row of results.csv is values() of it, in the order of the
// scene's columns() (scene.h).
#pragma once

#include <optional>
#include <vector>

namespace softglass::macro {

/// A computed quantity with its error estimates, all in the quantity's unit
/// (docs/macro.md, "Error estimates").
struct Estimate {
  double value = 0.0;
  double discretisation_error = 0.0;  ///< its change over the last refinement
  double regularisation_error = 0.0;  ///< from ε (regularised) or the ALG2 iterations
};

/// What one operating point cost.
struct SolveCost {
  unsigned cells = 0, dofs = 0;
  unsigned iterations = 0;  ///< Newton (or ALG2) iterations, all meshes
  double wall_time = 0.0;   ///< [s]
};

/// Which quantity a scene reports first.
enum class MainQuantity {
  torque,     ///< M [N m]: Couette, cone–plate, parallel plates
  flow_rate,  ///< Q [m^3/s] (a channel: [m^2/s] per unit width)
  own,        ///< a Stokes scene's own (its first column: pressure drop, drag, ...)
};

struct SceneResult {
  MainQuantity quantity = MainQuantity::own;
  Estimate main{};
  /// The main quantity's closed form for the ideal geometry, where there is one.
  std::optional<double> ideal_geometry{};
  std::optional<double> normal_force{};  ///< F [N] on the plate (materials with N1)
  std::optional<double> max_velocity{};  ///< [m/s], pressure-driven flows
  std::vector<double> own{};             ///< a Stokes scene's further columns
  double yielded_fraction = 0.0;         ///< [1]
  SolveCost cost{};

  /// The torque; std::logic_error unless the scene is a rotational rheometer.
  const Estimate& torque() const;

  /// The results.csv row: main with its two errors, the ideal geometry and
  /// the relative deviation from it, the normal force, the maximum velocity
  /// (those present), own, the yielded fraction and the cost.
  std::vector<double> values() const;

  /// Every field as numbers (for MPI), and back.
  std::vector<double> pack() const;
  static SceneResult unpack(const std::vector<double>& packed);
};

}  // namespace softglass::macro
