// A scene: one geometry of docs/macro.md with its reduced formulation, solved at a
// list of operating points (rotation rates or pressure gradients), each giving
// one row of the results table.
//
// Every scene is declared in the scene file's ParameterHandler (so that an
// unknown key anywhere is an error) and built by make_scene() for the one the
// file selects with `set scene = ...`.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/registry.h"
#include "common/unit_table.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/material.h"
#include "macro/scenes/scene_result.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro {

/// The column whose value is undefined, and written NaN, where the ideal
/// geometry's value is 0 (below the yield point of a pressure-driven flow):
/// the reduced scenes make it, the results file lets its NaN through.
inline constexpr const char* kUndefinedWhereIdealIsZero = "relative_deviation_from_ideal";

/// How a rotational rheometer reports what it measures (angular velocity Ω,
/// torque M) as a shear rate and a stress: γ̇ = strain_constant · Ω and
/// τ = stress_constant · M, the standard conversions of the geometry (what the
/// instrument's software applies; `convention` says which).
struct InstrumentConstants {
  double strain_constant;  // [1/rad]
  double stress_constant;  // [Pa/(N m)]
  std::string convention;
};

/// The scene's coarse mesh, before the solver refines it: the lengths a solve
/// works with and the size its cost grows from.
struct MeshExtent {
  unsigned dimension = 0;
  std::size_t cells = 0;
  double smallest_cell = 0.0;   ///< [m] the shortest distance between two vertices of a cell
  double largest_extent = 0.0;  ///< [m] the diagonal of the mesh's bounding box
  /// [m^3] the material's volume (per unit depth, [m^2], for plane sections):
  /// the outputs are integrals over it.
  double volume = 0.0;
  /// What an unknown costs relative to a scalar scene's (the cost model of
  /// docs/macro.md, app/operating_points.h).
  double relative_cost = 1.0;
};

class Scene {
 public:
  virtual ~Scene() = default;
  /// One line: geometry, formulation and boundary conditions.
  virtual std::string description() const = 0;
  /// The operating-point column (rotation_rate [rad/s] or pressure_gradient [Pa/m]).
  virtual Column drive() const = 0;
  /// The result columns of a row: the order of SceneResult::values().
  virtual std::vector<Column> columns() const = 0;
  /// Solves at one operating point (warm-started from the previous one).
  virtual SceneResult solve(double drive) = 0;
  /// The shear rate γ̇_c that sets the regularisation at one operating point
  /// (docs/macro.md: ε = relative rate scale · γ̇_c) [1/s].
  virtual double characteristic_rate(double drive) const = 0;
  virtual MeshExtent mesh_extent() const = 0;
  /// The fields of the last solved point, for ParaView.
  virtual void write_vtu(const std::filesystem::path& file) const = 0;
  /// Rotational rheometers: the instrument's conversions (none for channels,
  /// pipes and the Stokes scenes).
  virtual std::optional<InstrumentConstants> instrument() const { return std::nullopt; }
};

/// What a scene is made from: the scene file (its subsection is the scene's
/// name), the material, the solver settings, and the folder relative file
/// names (meshes) are taken from.
struct SceneSpec {
  dealii::ParameterHandler& prm;
  const Material& material;
  const fe::SolverSettings& settings;
  const std::filesystem::path& directory;
};

/// A registered scene (common/registry.h): name, summary, factory, and the
/// declaration of its subsection (its entries are deal.II parameters with
/// their own patterns, so it declares no registry coefficients).
struct SceneEntry : ComponentEntry<Scene, SceneSpec> {
  void (*declare)(dealii::ParameterHandler& prm) = nullptr;
};

/// Every scene (registered_scenes.h); `set scene` accepts the registry's names.
const Registry<SceneEntry>& scenes();

/// Declares `scene` and the subsection of every scene.
void declare_scenes(dealii::ParameterHandler& prm);

/// The selected scene, its parameters validated (InputError naming the entry).
/// Relative file names in the scene (meshes) are taken from `scene_directory`.
std::unique_ptr<Scene> make_scene(dealii::ParameterHandler& prm, const Material& material,
                                  const fe::SolverSettings& settings,
                                  const std::filesystem::path& scene_directory);

}  // namespace softglass::macro
