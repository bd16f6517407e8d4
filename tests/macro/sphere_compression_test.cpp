// The finite-element sphere between plates (macro/particle/sphere_compression.h):
// Hertz's law at small indentation, the force as the derivative of the stored
// energy, volume conservation, the large-deformation stiffening, and the
// settings it refuses. A coarse mesh keeps it to seconds; the tolerances are
// what that mesh reaches (docs/fidelity.md gives the converged law).
#include "macro/particle/sphere_compression.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.h"

namespace softglass::macro::particle {
namespace {

SphereCompressionSettings coarse() {
  SphereCompressionSettings s;
  s.global_refinements = 2;
  s.pole_refinements = 4;
  return s;
}

// Hertz for a sphere on a rigid plane, in the pair variables: F = (4/3) ε^{3/2}.
double hertz(double eps) {
  return 4.0 / 3.0 * std::pow(eps, 1.5);
}

TEST(SphereCompression, SmallIndentationFollowsHertz) {
  SphereCompression sphere(coarse());
  // δ/R = 2.5e-3 (ε = 0.01): contact radius √(Rδ) = 0.05 R.
  const CompressionState s = sphere.compress_to(2.5e-3);
  EXPECT_NEAR(pair_force(s) / hertz(pair_deformation(s)), 1.0, 0.03);
  EXPECT_NEAR(s.contact_radius / std::sqrt(2.5e-3), 1.0, 0.15);  // quadrature points only
}

TEST(SphereCompression, ForceIsTheDerivativeOfTheStoredEnergy) {
  SphereCompression sphere(coarse());
  // Simpson's rule over three close equilibria: Π(δ₂) − Π(δ₀) = ∫ f dδ. The
  // discrete f(δ) has kinks where a quadrature point enters the contact, which
  // Simpson's rule does not see: 1.1e-4 here, against the factor 2π or the
  // halves of a wrong force or energy this guards.
  const double d0 = 0.02, d1 = 0.021, d2 = 0.022;
  const CompressionState a = sphere.compress_to(d0);
  const CompressionState b = sphere.compress_to(d1);
  const CompressionState c = sphere.compress_to(d2);
  const double work = (d2 - d0) / 6.0 * (a.force + 4.0 * b.force + c.force);
  EXPECT_NEAR((c.energy - a.energy) / work, 1.0, 3e-4);
}

TEST(SphereCompression, NearlyIncompressibleAndStiffeningBeyondHertz) {
  SphereCompressionSettings settings = coarse();
  settings.pole_refinements = 2;  // the contact is wide here
  SphereCompression sphere(settings);
  double last_ratio = 0.0;
  for (double delta : {0.03, 0.08, 0.15}) {
    const CompressionState s = sphere.compress_to(delta);
    // κ = 10³ μ: |J̄ − 1| ~ p/κ, with p a few E* at most.
    EXPECT_LT(s.volume_change, 1e-2) << "delta " << delta;
    const double ratio = pair_force(s) / hertz(pair_deformation(s));
    EXPECT_GT(ratio, last_ratio) << "delta " << delta;  // Tatara; Liu, Williams & Briscoe
    last_ratio = ratio;
  }
  EXPECT_GT(last_ratio, 1.08);  // converged: 1.18 at δ = 0.15 R (docs/fidelity.md)
}

TEST(SphereCompression, RefusesNonPhysicalSettings) {
  SphereCompressionSettings s = coarse();
  s.poisson_ratio = 0.5;  // κ = ∞: not a displacement formulation
  EXPECT_THROW(SphereCompression{s}, InputError);
  s = coarse();
  s.penalty = -1.0;
  EXPECT_THROW(SphereCompression{s}, InputError);
  s = coarse();
  s.penalty = std::nan("");
  EXPECT_THROW(SphereCompression{s}, InputError);
  SphereCompression sphere(coarse());
  EXPECT_THROW(sphere.compress_to(0.6), InputError);
  EXPECT_THROW(sphere.compress_to(std::nan("")), InputError);
}

}  // namespace
}  // namespace softglass::macro::particle
