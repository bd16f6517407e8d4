// The slip law of a plug: the particles next to a smooth wall sliding over it
// as one rigid block at speed V (docs/physics.md, "Wall slip").
//
// Below the yield stress the material between smooth walls does not shear:
// it slides on the wall films, and its wall contacts keep the loads they had
// at rest (the wall runs measure both: bulk rate < 1e-3 of the apparent rate,
// contacts per area and load per contact unchanged to 1 % up to σ_y). Every
// film then slides at w = V e_x, and the wall stress is the sum of the film
// drags per wall area A (model/wall_films.h, model/film.h):
//     σ_w = (1/A) Σ_k a_k √V          for V ≥ w*_k,
//         = (1/A) Σ_k a_k V /√w*_k    below (the film's rest thickness h0),
// with a_k = (¾ γ̃ R_k |f_k| √ε_k)^{1/2} and w*_k = (h0 a_k/(π γ̃ ε_k R_k²))² in
// the run's reduced units (V in γ̇ R, σ in E*). In the speed
//     U = V η_s/(E* R) = γ̃ · (V in units of γ̇ R)
// the rate drops out: a_k √V = (¾ R_k |f_k| √ε_k U)^{1/2}, and the crossover
// U*_k = γ̃ w*_k = (h0/(π ε_k R_k²))² ¾ R_k |f_k| √ε_k depends on the contact
// alone. So the plug's slip law σ_w(U) is a property of the packing at rest —
// its wall contacts' loads — and holds at any rate, including those far below
// what the dynamics can reach (experiments slip at U ~ 1e-9): quadratic,
// V ∝ σ_w², above the films' crossovers, linear (Navier) below.
#pragma once

#include <vector>

#include "micro/contact/wall_contacts.h"

namespace softglass::micro {

class PlugSlipLaw {
 public:
  /// The law of a plug held by `contacts` (both walls) of a cell of wall area
  /// `area`, films of rest thickness h0 (units of R; 0: the paper's √|w| law).
  PlugSlipLaw(const WallContacts& contacts, double area, double rest_thickness);

  /// σ_w/E*, the two walls' mean, at slip speed U = V η_s/(E* R).
  double wall_stress(double speed) const;
  /// (1/A) Σ a_k/√γ̃: the coefficient S of σ_w = S √U above every crossover.
  double coefficient() const { return coefficient_; }
  /// The films' crossover speeds U*_k, ascending (all 0 without a rest thickness).
  std::vector<double> crossovers() const;

 private:
  double area_ = 1.0, coefficient_ = 0.0;
  std::vector<double> a_, crossover_;  // per film: a_k(γ̃ = 1), U*_k
};

}  // namespace softglass::micro
