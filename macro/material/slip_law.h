// Wall slip: the shear stress a smooth wall exerts on the material sliding
// over it, as a function of the slip velocity, one law per file.
//
// A soft glass on a smooth wall slides on a thin solvent film (Meeker,
// Bonnecaze & Cloitre, PRL 92, 198302 (2004)): the wall no longer fixes the
// velocity of the material next to it, but relates the wall shear stress σ_w
// to the slip velocity V_s, the velocity of the material at the wall relative
// to the wall. A slip law is that relation for V_s ≥ 0,
//
//     σ_w = σ_w(V_s),     σ_w(0) = 0,     increasing,
//
// extended as an odd function to V_s < 0 (the wall drags whichever way the
// material slides). It is the one-dimensional analogue of a shear law
// (shear_law.h), with V_s in place of γ̇, and enters the finite-element
// solvers the same way: through a dissipation potential D(V) = ∫₀^V σ_w,
// convex because σ_w increases (fe/scalar_problem.h derives the boundary
// term), and a regularised form whose derivative is finite everywhere, for
// Newton's method.
//
// The laws, one file each in slip_laws/, are registered (common/registry.h)
// in slip_laws/registered_slip_laws.h; `slip/law` of a scene file accepts the
// registry's names (slip_parameters.h reads them).
#pragma once

#include <memory>
#include <string>

#include "common/registry.h"

namespace softglass::macro {

/// σ_w and dσ_w/dV at one slip velocity.
struct WallStress {
  double value = 0.0;       ///< σ_w [Pa]
  double derivative = 0.0;  ///< dσ_w/dV_s [Pa s/m], > 0
};

class SlipLaw {
 public:
  virtual ~SlipLaw() = default;

  /// The registry name.
  virtual std::string name() const = 0;

  /// σ_w(V) [Pa] for V ≥ 0 [m/s]: 0 at 0 (its limit from above where the law
  /// has a slip yield stress), increasing.
  virtual double stress(double velocity) const = 0;

  /// The inverse V_s(σ_w) [m/s] for σ_w ≥ 0: zero up to a slip yield stress.
  virtual double velocity(double stress) const = 0;

  /// The law regularised at the velocity scale ε_V > 0 [m/s], for any real V
  /// (odd in V): smooth, strictly increasing, with a finite positive
  /// derivative everywhere, and tending to the law at every V ≠ 0 as ε_V → 0.
  virtual WallStress regularised(double velocity, double velocity_scale) const = 0;
};

/// What a slip law is made from: its coefficients in SI, as the scene file's
/// `subsection slip` states them (slip_parameters.h). A law that does not use
/// one requires it to be at its default (0), so that nothing set is ignored.
struct SlipLawSpec {
  double coefficient = 0.0;   ///< β [m/s/Pa^p]
  double exponent = 0.0;      ///< p [1]
  double yield_stress = 0.0;  ///< σ_s [Pa]
};
using SlipLawEntry = ComponentEntry<SlipLaw, SlipLawSpec>;

/// Every slip law (slip_laws/registered_slip_laws.h).
const Registry<SlipLawEntry>& slip_laws();

/// The slip law called `name`; InputError for an unknown name, or for
/// coefficients the law does not allow (naming the entry of `subsection slip`).
std::unique_ptr<SlipLaw> make_slip_law(const std::string& name, const SlipLawSpec& spec);

}  // namespace softglass::macro
