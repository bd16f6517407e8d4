// FIRE 2.0 energy minimisation (Bitzek et al., PRL 97, 170201 (2006);
// Guénolé et al., Comput. Mater. Sci. 175, 109584 (2020)).
//
// Damped dynamics with unit masses, semi-implicit Euler, velocity mixed towards
// the force direction while the power F·v stays positive; on an uphill move the
// step is halved, the particles are pulled back half a step and stopped. The
// largest stable step follows the stiffness: dt_max = c/√λ with λ the Gershgorin
// bound of the Hessian (contact_forces.h), so no step has to be guessed.
//
// Convergence: the residual max_α|F_α| / ⟨|f_c|⟩ (largest net force over the mean
// contact force, scale-free) falls below `force_tolerance`; or the packing is
// unjammed: its mean contact force has fallen below `unjammed_force` (units E*R²;
// 1e-12 is an overlap of about 1e-8 R), so there is no force network to balance
// and the relative residual, a ratio of vanishing forces, means nothing.
#pragma once

#include <cstddef>

#include "micro/model/contact_system.h"

namespace softglass::micro {

struct FireSettings {
  double force_tolerance = 1e-9;
  std::size_t max_iterations = 500000;
  double step_fraction = 0.5;  // dt_max = step_fraction / √λ (stable below 2)
  double unjammed_force = 1e-12;

  void validate() const;
};

struct FireResult {
  std::size_t iterations = 0;
  double residual = 0.0;  // max|F| / mean contact force
  double energy = 0.0;    // Σ R_c³ W(ε), units E* R³
  bool converged = false;
  bool unjammed = false;  // converged because the contacts carry no force
};

/// Relaxes `system` at fixed cell and strain towards force balance.
FireResult minimise_fire(ContactSystem& system, const FireSettings& settings);

/// Residual of computed forces: max|F_α| / ⟨|f_c|⟩, or 0 without contacts.
double force_residual(const ContactField& field);

}  // namespace softglass::micro
