// The large-deformation contact law of one elastic sphere, computed by finite
// elements: a nearly incompressible neo-Hookean sphere of radius R pressed between
// two rigid, frictionless plates (the experiment and the calculations of Tatara
// 1991 and Liu, Williams & Briscoe 1998, the paper's ref. 6).
//
// Why this problem is the pair law of the particle model. Two equal spheres
// pressed together meet on their plane of symmetry, which is frictionless by
// symmetry: each sphere is pressed against a rigid frictionless plane. With
// its centre held, the plane's displacement δ towards the centre is half the
// overlap h of the undeformed spheres, so the pair law's deformation is
// ε = h/R_c = 2δ/(R/2) = 4δ/R and its reduced force F = f/(E* R_c²) = 4f/(E* R²)
// (micro/contact/contact_law.h). The sphere between two plates has a second
// contact at its far pole, as a particle of a packing has its other
// neighbours; at small δ that second contact adds only a bulk compression of
// relative order √(δ/R) to Hertz, at large δ it is part of the stiffening.
//
// The problem is axisymmetric: the meridian half-plane (r, z) of the upper
// quarter of the sphere, z ≥ 0, with the plate at z = R − δ, the axis r = 0 and
// the equator z = 0 (the plane of symmetry between the two plates) as
// frictionless symmetry lines. Total Lagrangian, Q2 displacements, and the
// potential energy
//
//     Π(u) = Σ_cells [ ∫ μ/2 (J^(−2/3) I₁ − 3) dV + κ/2 (J̄ − 1)² V ]
//            + ∫_Γ k/2 ⟨z + u_z − (R − δ)⟩₊² dA ,          dV = 2π r dr dz,
//
// with F the axisymmetric deformation gradient (its hoop stretch 1 + u_r/r),
// J = det F, I₁ = tr FᵀF, and J̄ the mean dilatation of each cell (∫J dV / V):
// the volumetric energy of a nearly incompressible solid taken on the cell
// mean is the Q2–P0 mixed method with the pressure eliminated cell by cell
// (Nagtegaal, Parks & Rice 1974; Simo, Taylor & Pister 1985), which does not
// lock and keeps the problem a minimisation. The plate is a stiff penalty k
// on the reference surface Γ: its compliance 1/k per area lies in series
// with the sphere's local one, about a/E*, a relative error of order
// 1/(k a) in the force — 0.4 % at the default k = 10⁴ E*/R and the smallest
// contact radius a = 0.024 R of the bundled table, measured against
// k = 10⁶ (docs/fidelity.md), whose stiffer contact costs Newton its
// convergence (Wriggers, Computational Contact Mechanics, ch. 6). Gradient and Hessian of Π are
// exact, by automatic differentiation (Sacado, as in deal.II's step-72), so Newton converges
// quadratically, and the force on the plate, ∂Π/∂δ = ∫ k ⟨gap⟩₊ dA, is the
// derivative of the stored energy — an identity the tests check. The paper's
// ν = 1/2 is approached by ν = 0.4995 (κ = 10³ μ; the force changes by
// O(μ/κ)); μ = E*(1 − ν) since E* = E/(2(1 − ν²)).
#pragma once

#include <memory>

namespace softglass::macro::particle {

struct SphereCompressionSettings {
  /// Uniform refinements of the quarter disc's three coarse cells.
  unsigned int global_refinements = 3;
  /// Further refinements graded towards the contact (cells within a few of
  /// their diameters of the pole): the contact radius √(Rδ) of small δ is
  /// resolved by about two cells at δ = 2.5e-3 R with the defaults.
  unsigned int pole_refinements = 5;
  /// Poisson's ratio, below 1/2 (the incompressible sphere; 0.4995 is κ = 10³ μ).
  double poisson_ratio = 0.4995;
  /// The plate's penalty stiffness per unit area, units of E*/R.
  double penalty = 1e4;
  /// Newton stops when a correction moves no point by more than this × R
  /// (the round-off floor of the penalised system is near 1e-10).
  double newton_tolerance = 1e-9;
  unsigned int max_newton_iterations = 40;

  void validate() const;  // InputError naming the setting
};

/// One equilibrium of the sphere between the plates; lengths in R, forces in
/// E* R², energies in E* R³.
struct CompressionState {
  double indentation = 0.0;     // δ/R, the plate's displacement towards the centre
  double force = 0.0;           // f/(E* R²), the force on one plate
  double energy = 0.0;          // Π: the elastic energy of the half sphere z ≥ 0, plus the
                                // penalty's
  double contact_radius = 0.0;  // a/R, the deformed radius of the contact
  double volume_change = 0.0;   // max |J̄ − 1| over the cells
  unsigned int newton_iterations = 0;
};

class SphereCompression {
 public:
  explicit SphereCompression(const SphereCompressionSettings& settings);
  ~SphereCompression();
  SphereCompression(const SphereCompression&) = delete;
  SphereCompression& operator=(const SphereCompression&) = delete;

  /// Moves the plate on to δ/R = `indentation` (beyond the present one: the
  /// sphere is only loaded), in steps of at most a quarter of δ, and returns
  /// the equilibrium there; NumericalError if even short steps do not
  /// converge (a finer mesh may).
  CompressionState compress_to(double indentation);

  unsigned int n_dofs() const;
  unsigned int n_cells() const;

 private:
  class Solver;  // the deal.II finite-element solver (sphere_compression.cpp)
  std::unique_ptr<Solver> solver_;
};

/// The pair law's reduced variables (micro/contact/contact_law.h) of a
/// sphere–plate equilibrium: ε = 4δ/R, F = 4 f/(E* R²).
inline double pair_deformation(const CompressionState& s) {
  return 4.0 * s.indentation;
}
inline double pair_force(const CompressionState& s) {
  return 4.0 * s.force;
}

}  // namespace softglass::macro::particle
