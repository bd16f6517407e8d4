// How a scene is solved: the method, its regularisation, the discretisation
// and the adaptive loop. Presets fix them all (fast, standard, accurate);
// the `subsection solver` of a scene file may override any of them.
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro::fe {

/// Continuation divides ε by this per stage; 10 keeps each stage within a few
/// Newton iterations of the previous one for n down to 0.3 (measured). The
/// regularisation error estimate compares ε with kContinuationFactor·ε.
inline constexpr double kContinuationFactor = 10.0;
/// Damped Newton after a short step: the tangent viscosity τ' is kept at least
/// kTangentFloor times the secant viscosity η.
inline constexpr double kTangentFloor = 0.1;

/// regularised: Papanastasiou or Bercovier–Engelman viscosity, Newton with an
/// exact line search, continuation in ε. augmented-lagrangian: ALG2 on the
/// unregularised law (yield surfaces where the local stress reaches τ_y).
enum class Method { regularised, augmented_lagrangian };

struct SolverSettings {
  std::string preset = "standard";
  Method method = Method::regularised;
  std::string regularisation = "papanastasiou";
  /// ε/γ̇_c: the regularisation rate scale relative to the scene's shear rate.
  double relative_rate_scale = 1e-4;
  unsigned fe_degree = 2;
  /// Uniform refinements of the scene's base mesh before the adaptive loop.
  unsigned global_refinements = 1;
  /// Solve–estimate–refine cycles after the first solve; ≥ 1 for the scalar
  /// scenes, because the discretisation error is estimated from the change
  /// over the last cycle (the Stokes solver refines once uniformly first and
  /// accepts 0).
  unsigned adaptive_cycles = 2;
  /// Fraction of cells refined per cycle (largest Kelly indicators), on top of
  /// the cells a yield surface crosses.
  double refine_fraction = 0.3;
  /// Newton stops when the update is below this times max |u|.
  double newton_tolerance = 1e-10;
  unsigned max_newton_iterations = 60;
  /// ALG2: penalty relative to the scene's viscosity scale, iteration cap and
  /// the tolerance on the relative constraint residual ‖s∇u − γ‖/‖γ‖.
  double al_relative_penalty = 1.0;
  unsigned al_max_iterations = 5000;
  double al_tolerance = 1e-6;
  /// The ranks that share one operating point's mesh (2D sections of the
  /// scalar scenes; 1D sections and the Stokes scenes solve on one rank).
  MPI_Comm mesh_communicator = MPI_COMM_SELF;
};

/// The presets, by name: fast, standard, accurate.
SolverSettings preset(const std::string& name);
std::vector<std::string> preset_names();

/// `subsection solver`: preset plus optional overrides (empty = the preset's).
void declare_solver_settings(dealii::ParameterHandler& prm);
SolverSettings read_solver_settings(dealii::ParameterHandler& prm);

}  // namespace softglass::macro::fe
