// A film of finite rest thickness h0 (micro/model/film.h): the drag is that of
// a Couette film of area A = π ε R_c² and thickness max(δ_EHD, h0), where the
// paper's law implies δ_EHD = π γ̃ ε R_c² u / f_EHD(u) (reduced units). Checked
// here against that formulation, written independently of the engine's
// secant form: the law itself (continuity, derivative, convexity), the
// implicit velocities it gives, and what it was introduced for — a linear
// regime of the amplitude sweep, where the paper's √u law has none
// (docs/oscillation.md).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "micro/model/ehd_drag.h"
#include "micro/model/film.h"
#include "micro/protocol/oscillatory_run.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

constexpr double kPi = std::numbers::pi;

// The drag of a Couette film of thickness max(δ_EHD, h0) at sliding speed u,
// for a contact of radius R_c, deformation ε and EHD coefficient a (f_EHD =
// a √u).
double couette_drag(double u, double a, double rc, double eps, double gamma_tilde, double h0) {
  const double area_viscosity = kPi * gamma_tilde * eps * rc * rc;  // η A in reduced units
  const double ehd_thickness = area_viscosity * u / (a * std::sqrt(u));
  return area_viscosity * u / std::max(ehd_thickness, h0);
}

TEST(FilmRestThickness, TheLawIsACouetteFilmOfTheThickerThickness) {
  const double gamma_tilde = 1e-6, rc = 0.5, eps = 0.2, h0 = 2e-3;
  const double a = film_coefficient(gamma_tilde, rc, 0.05, eps);
  const FilmLaw law{a, film_crossover(h0, gamma_tilde, a, rc, eps)};
  // At the crossover the EHD film is exactly h0 thick.
  const double w = law.crossover;
  EXPECT_NEAR(kPi * gamma_tilde * eps * rc * rc * w / (a * std::sqrt(w)), h0, 1e-12 * h0);
  for (double u : {1e-3 * w, 0.5 * w, 0.999 * w, w, 1.001 * w, 3 * w, 1e3 * w}) {
    EXPECT_NEAR(law.secant(u) * u, couette_drag(u, a, rc, eps, gamma_tilde, h0),
                1e-12 * couette_drag(u, a, rc, eps, gamma_tilde, h0))
        << u / w;
    // The potential's derivative is the drag; its second difference is >= 0.
    const double d = 1e-6 * u;
    EXPECT_NEAR((law.potential(u + d) - law.potential(u - d)) / (2 * d), law.secant(u) * u,
                1e-6 * law.secant(u) * u)
        << u / w;
    EXPECT_GE(law.potential(u + d) + law.potential(u - d) - 2 * law.potential(u),
              -1e-12 * law.potential(u));
  }
  // Without a rest thickness: the paper's law at every speed.
  const FilmLaw paper{a, film_crossover(0.0, gamma_tilde, a, rc, eps)};
  EXPECT_EQ(paper.crossover, 0.0);
  EXPECT_DOUBLE_EQ(paper.secant(1e-8) * 1e-8, a * std::sqrt(1e-8));
}

// The films' law over arrays (what the implicit step's evaluation of Φ uses)
// is FilmLaw's, film by film, to the last bit: a film with and without a rest
// thickness, at rest, below, at and above its crossover. Exact equality is the
// claim (the two compute the same correctly rounded operations in the same
// order), whichever instruction set's variant the processor runs.
TEST(FilmRestThickness, TheLawOverArraysIsTheLawFilmByFilm) {
  const double gamma_tilde = 1e-6, rc = 0.5, eps = 0.2;
  const double a = film_coefficient(gamma_tilde, rc, 0.05, eps);
  std::vector<double> coefficient, crossover, squared;
  for (double h0 : {0.0, 2e-3}) {
    const double w_star = film_crossover(h0, gamma_tilde, a, rc, eps);
    const double scale = h0 > 0.0 ? w_star : 1e-4;
    for (double u : {0.0, 1e-3, 0.5, 0.999, 1.0, 1.001, 3.0, 1e3}) {
      coefficient.push_back(a);
      crossover.push_back(w_star);
      squared.push_back(u * scale * u * scale);
    }
  }
  coefficient.push_back(0.0);  // a pair without EHD film (a dashpot alone)
  crossover.push_back(0.0);
  squared.push_back(1e-6);
  const std::size_t n = squared.size();
  std::vector<double> speed = squared, secant(n), potential(n);
  evaluate_films(coefficient, crossover, speed, secant, potential);
  for (std::size_t k = 0; k < n; ++k) {
    const FilmLaw law{coefficient[k], crossover[k]};
    const double u = std::sqrt(squared[k]);
    EXPECT_EQ(speed[k], u) << k;
    EXPECT_EQ(secant[k], law.secant(u)) << k;
    EXPECT_EQ(potential[k], law.potential(u)) << k;
  }
}

// The implicit velocities with films of rest thickness satisfy ζv = F^e +
// F^film(v) with the Couette-film drag above.
TEST(FilmRestThickness, ImplicitVelocitiesBalanceTheCouetteFilmDrag) {
  const PackingSpec spec = testing::small_packing_spec(1);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);
  ContactSystem system(packing.particles, packing.box, law, spec.skin);
  const double gamma_tilde = 1e-6, h0 = 1e-3;
  const ContactField& field = system.compute_forces({.contacts = true});
  const ContactList& c = field.contacts;
  std::vector<double> zeta;
  for (double r : system.particles().radius) zeta.push_back(6 * kPi * gamma_tilde * r / 0.01);
  EhdDrag drag({.rest_thickness = h0, .tolerance = 1e-10});
  std::vector<Vec3> v(system.size(), Vec3::Zero());
  drag.solve(c, gamma_tilde, 1.0, zeta, field.force, v);
  std::vector<Vec3> film(system.size(), Vec3::Zero());
  std::size_t linear = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Vec3 q = v[c.i[k]] - v[c.j[k]] + Vec3(c.separation[k].y(), 0, 0);
    const Vec3 n = c.separation[k].normalized();
    const Vec3 w = q - n * n.dot(q);
    const double u = w.norm();
    if (u == 0.0) continue;
    const double a =
        film_coefficient(gamma_tilde, c.contact_radius[k], c.force[k], c.deformation[k]);
    const double f = couette_drag(u, a, c.contact_radius[k], c.deformation[k], gamma_tilde, h0);
    linear += f < a * std::sqrt(u) * (1 - 1e-12);
    film[c.i[k]] -= f * w / u;
    film[c.j[k]] += f * w / u;
  }
  double worst = 0.0, scale = 1.0;
  for (const Vec3& x : v) scale = std::max(scale, x.norm());
  for (std::size_t a = 0; a < v.size(); ++a)
    worst = std::max(worst, (zeta[a] * v[a] - field.force[a] - film[a]).norm() / zeta[a] / scale);
  std::printf("[ measured ] %zu of %zu films in the linear regime, residual %.2e\n", linear,
              c.size(), worst);
  EXPECT_GT(linear, c.size() / 10) << "the test must reach the linear regime";
  EXPECT_LT(linear, c.size()) << "and the EHD one";
  EXPECT_LE(worst, 1e-9);
}

// What the rest thickness is for: the amplitude sweep's linear plateau. With
// h0 the small-amplitude loss modulus no longer depends on the amplitude
// (the paper's law gives G″ ∝ γ0^{-1/2}: 3.1× between these two), and the
// storage modulus is the static one.
TEST(FilmRestThickness, RestoresTheLinearViscoelasticPlateau) {
  omp_set_num_threads(1);
  const PackingSpec spec = testing::small_packing_spec(1);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);
  const auto loss_and_storage = [&](double amplitude, double h0) {
    OscillationProtocol protocol;
    protocol.amplitude = amplitude;
    protocol.frequency = 1e-8;
    protocol.samples_per_cycle = 16;
    ShearModel model;
    model.gamma_tilde = protocol.peak_gamma_tilde();
    model.drag.rest_thickness = h0;
    OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model,
                         ShearDrive::oscillatory(amplitude));
    const auto integrator =
        make_integrator(oscillation_integrator({}, protocol, model.drag.stokes.reference));
    const OscillationResult r = run_oscillation(flow, *integrator, protocol);
    EXPECT_TRUE(r.converged) << r.stop_reason;
    return std::pair(r.summary["loss"].mean, r.summary["storage"].mean);
  };
  const auto [small, g_small] = loss_and_storage(1e-4, 3e-3);
  const auto [large, g_large] = loss_and_storage(1e-3, 3e-3);
  ContactSystem at_rest(packing.particles, packing.box, law, spec.skin);
  const double static_modulus = shear_modulus(at_rest).flow_gradient_modulus;
  std::printf(
      "[ measured ] h0 = 3e-3: G'' = %.4g, %.4g at gamma0 = 1e-4, 1e-3; G' = %.5g, %.5g, "
      "static %.5g\n",
      small, large, g_small, g_large, static_modulus);
  EXPECT_NEAR(small / large, 1.0, 0.05);
  EXPECT_NEAR(g_small, static_modulus, 0.01 * static_modulus);
}

}  // namespace
}  // namespace softglass::micro
