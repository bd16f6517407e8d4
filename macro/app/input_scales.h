// The scales a solve derives from the input, checked before any solve.
//
// Every entry has its own range (a radius > 0, a flow index in (0, 2]), but
// values that each pass it can still make what a solve derives from them
// overflow: a radius of 1e308 m gives a mesh of infinite size, a yield stress
// of 1e308 Pa a viscosity whose square is infinite. The solver then fails far
// from the cause ("rate scale = inf", a failed factorisation: exit code 1).
// Here, once for every scene, the scales a solve works with are derived from
// the scene, the material, the solver settings and the operating points —
// mesh sizes, the characteristic and regularisation rates, stress, viscosity,
// power, the main output (torque, flow rate, ...) and the normal stresses —
// and each must lie within kScaleRange (in SI units), so that the products and
// squares the solver forms (norms, r³η in the assembly) stay finite. A scale
// outside it is bad input: one InputError naming the scale, its value, the
// operating point, and the entry that most likely caused it — of the values
// it is made from, the one farthest from 1 in order of magnitude — with its
// file and line. Two dimensionless quantities are bounded more tightly, by
// what the solver was measured to converge on: the Bingham number and the
// flow index.
#pragma once

#include <filesystem>
#include <vector>

#include "common/parameter_input.h"
#include "common/si_range.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/material.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

/// Every derived scale s must satisfy 1/kScaleRange <= |s| <= kScaleRange.
inline constexpr double kScaleRange = kSiRange;

/// The Bingham number Bi = τ_y/(K γ̇_cⁿ) at every operating point, the
/// one dimensionless group the solver's convergence depends on (the plug's
/// viscosity τ_y/ε against the flowing K γ̇ⁿ⁻¹): up to this. Measured with
/// bench/solver_envelope.sh: the regularised Newton solve converges at every
/// preset up to Bi ≈ 1e13 and fails at 1e14 (accurate preset); real soft
/// glasses reach 1e4 at the lowest rates a rheometer applies.
inline constexpr double kLargestBinghamNumber = 1e10;

/// The flow index n, whose entry admits (0, kLargestFlowIndex] (material.h):
/// from kSmallestFlowIndex. The rate (Δτ/K)^{1/n} of smaller n overflows within
/// a gap, and the solve fails (bench/solver_envelope.sh: n = 0.01 converges at
/// every preset, 0.003 does not with a 0.1 mm bob in a 15.2 mm cup); fitted
/// flow curves of soft glasses give 0.1 … 1.
inline constexpr double kSmallestFlowIndex = 0.01;

/// Every number `entries` set (scene, material, sweep) is itself a scale:
/// 0 or within kScaleRange. Called before the scene is built, whose mesh
/// generators fail on such values.
void check_entry_scales(const std::vector<SetEntry>& entries,
                        const std::filesystem::path& scene_file);

/// `entries`: what the input files set (SceneInput::entries), and the
/// measured operating points as entries of subsection "measurement" where
/// they come from a data file. `scene_file` heads the message.
void check_derived_scales(const Scene& scene, const Material& material,
                          const fe::SolverSettings& settings, const std::vector<double>& points,
                          const std::vector<SetEntry>& entries,
                          const std::filesystem::path& scene_file);

}  // namespace softglass::macro::app
