// Steady shear sanity: a short run of the paper's model (N = 300, φ = 0.8,
// γ̃ = 1e-4, seth2011, EHD on) has the signs the paper reports: σ > 0, a positive
// viscous part much smaller than the elastic one, and N2 < 0 (docs/physics.md; the paper).
#include <gtest/gtest.h>

#include <limits>

#include "common/errors.h"
#include "micro_test_support.h"

namespace softglass::micro {
namespace {

TEST(SteadyShear, StressSignsOfTheStationaryState) {
  const PackingSpec spec = testing::small_packing_spec(6, 0.8, 300);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);

  const ShearResult r = testing::shear_briefly(packing, law, spec.skin, 4.0).result;
  const ShearSummary& m = r.summary;

  const MeanEstimate& sigma = m["sigma"];
  const MeanEstimate& viscous = m["sigma_viscous"];
  const MeanEstimate& n2 = m["N2"];
  std::printf(
      "[ measured ] transient %.2f, averaged %.2f: sigma %.4e ± %.1e (viscous %.3e ± %.1e), "
      "N1 %.3e ± %.1e, N2 %.3e ± %.1e, sigma^e/sigma^v %.1f\n",
      m.transient_strain, m.averaged_strain, sigma.mean, sigma.standard_error, viscous.mean,
      viscous.standard_error, m["N1"].mean, m["N1"].standard_error, n2.mean, n2.standard_error,
      m.elastic_to_viscous);
  ASSERT_GE(m.averaged_strain, 1.0);

  // σ > 0 at every sample of the stationary part, not just on average.
  const std::vector<double> total = r.series.component("sigma");
  const std::vector<double> part = r.series.component("sigma_viscous");
  std::size_t first = 0;
  while (r.series.strain[first] - r.series.strain.front() < m.transient_strain) ++first;
  for (std::size_t k = first; k < total.size(); ++k) {
    EXPECT_GT(total[k], 0.0) << "strain " << r.series.strain[k];
    EXPECT_GT(part[k], 0.0) << "strain " << r.series.strain[k];
  }
  // Means: several standard errors from zero, with the paper's signs.
  EXPECT_GT(sigma.mean, 3.0 * sigma.standard_error);
  EXPECT_GT(viscous.mean, 3.0 * viscous.standard_error);
  EXPECT_LT(n2.mean, -2.0 * n2.standard_error);
  // The elastic stress dominates (the paper: σ^e ≥ 100 σ^v over its range; at
  // the fast end γ̃ = 1e-4 the ratio is smallest, so only ≫ 1 is asserted).
  EXPECT_GT(m.elastic_to_viscous, 10.0);
}

// A velocity that is not a number stops the run with a NumericalError naming
// it, wherever it sits among the particles: a maximum over the speeds alone
// passes a NaN by (max(s, NaN) is s) and the run would go on with it.
TEST(SteadyShear, NonFiniteVelocityIsAnError) {
  const PackingSpec spec = testing::small_packing_spec(3, 0.8, 200);
  const auto law = testing::named_law("seth2011");
  const Packing packing = make_packing(spec, law);
  ShearModel model;
  model.gamma_tilde = 1e-4;
  OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model);
  flow.sample_stress_from(std::numeric_limits<double>::infinity());  // no re-evaluation
  flow.evaluate();
  std::vector<Vec3> velocity(flow.system().particles().velocity);
  flow.accept_step_velocities(velocity);  // finite: accepted
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    for (const std::size_t at : {std::size_t{0}, velocity.size() / 2, velocity.size() - 1}) {
      std::vector<Vec3> broken = velocity;
      broken[at].y() = bad;
      EXPECT_THROW(flow.accept_step_velocities(broken), NumericalError) << bad << " at " << at;
    }
}

}  // namespace
}  // namespace softglass::micro
