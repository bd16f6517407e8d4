// The Taylor–Hood Stokes solver on plane Poiseuille flow of a
// Herschel–Bulkley material: with the exact fully developed profile
// (exact/channel.h) imposed at inlet and outlet and no slip on the walls, the
// exact solution is that profile everywhere and a pressure that falls
// linearly by G per unit length — plug, yield surfaces and all. (A
// traction-free outlet would not do: with the symmetric-gradient form the
// free outlet carries no shear stress, which Poiseuille flow has; the
// straight outflow of StokesDrive does, second test.)
#include <deal.II/grid/grid_generator.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "macro/exact/channel.h"
#include "macro/fe/stokes_flow_solver.h"

namespace softglass::macro::fe {
namespace {

using dealii::Point;
using dealii::Tensor;

// The channel of both tests: height 2H, length 4H, walls ids 2 and 3, inlet
// 0, outlet 1; a Newtonian and a Herschel–Bulkley law (plug of half-width ¼).
constexpr double H = 1.0, length = 4.0, G = 1.0;
const exact::PlaneChannel channel{.half_height = H, .pressure_gradient = G};
const HerschelBulkley kLaws[] = {newtonian(1.0), HerschelBulkley{0.25, 1.0, 0.5}};

dealii::Triangulation<2> channel_mesh() {
  dealii::Triangulation<2> mesh;
  dealii::GridGenerator::subdivided_hyper_rectangle(mesh, {8, 4}, Point<2>(0.0, -H),
                                                    Point<2>(length, H), true);
  return mesh;
}

SolverSettings channel_settings() {
  SolverSettings settings = preset("standard");
  settings.global_refinements = 1;
  settings.adaptive_cycles = 0;  // the uniform refinement suffices here; keeps the test quick
  return settings;
}

// The exact developed profile of `law` as boundary data; no slip.
std::function<Tensor<1, 2>(const Point<2>&)> developed(const HerschelBulkley& law) {
  return [law](const Point<2>& p) {
    return Tensor<1, 2>({exact::velocity(law, channel, p[1]), 0.0});
  };
}
const auto zero = [](const Point<2>&) { return Tensor<1, 2>(); };

TEST(FeStokes, PoiseuilleFlowOfAHerschelBulkleyMaterial) {
  for (const HerschelBulkley& law : kLaws) {
    StokesFlowSolver solver(channel_mesh(), shear_law(law), channel_settings());
    const auto inflow = developed(law);
    const double wall_rate = law.rate(G * H);
    const StokesResult r = solver.run({.velocity = {{0, inflow}, {1, inflow}, {2, zero}, {3, zero}},
                                       .characteristic_rate = wall_rate,
                                       .force_boundary = 1,
                                       .pressure_boundary = 0});
    // On the outlet the force on the boundary is ∫ p ds along x (∂u/∂x = 0
    // there), so the mean outlet pressure is force_x / 2H.
    const double drop = r.value.mean_pressure - r.value.force[0] / (2.0 * H);
    // Energy: the dissipation of developed flow is G Q per unit length. The
    // regularised material creeps in the plug at rates ~ε = 1e-4 γ̇_w, which
    // is the error allowed (macro.md: ≤ 1e-3 at the standard preset).
    const double Q = exact::flow_rate(law, channel);
    EXPECT_NEAR(r.value.dissipation / (G * Q * length), 1.0, 1e-3) << law.yield_stress;
    // The pressure drop from boundary tractions is less accurate where the
    // quasi-rigid plug meets the boundary: there η_ε ~ τ_y/ε multiplies the
    // discretisation error of D (measured 2.4e-3 for the HB law; for
    // the Newtonian one, below 1e-14).
    EXPECT_NEAR(drop / (G * length), 1.0, 5e-3) << law.yield_stress;
    // The centreline velocity is the exact plug speed.
    const auto u = solver.velocity_at({Point<2>(0.5 * length, 0.0)});
    EXPECT_NEAR(u[0][0] / exact::velocity(law, channel, 0.0), 1.0, 1e-3) << law.yield_stress;
  }
}

// The obstacle's and the contraction's outlet: developed flow leaves through
// a straight outflow (v = 0, zero normal traction) with p = 0 and its own
// profile, so the channel with the exact profile imposed at the inlet only
// has the same exact solution. Measured before this outlet, with a free one:
// a Newtonian pressure drop 2.5 % low over this channel.
TEST(FeStokes, StraightOutflowLetsDevelopedFlowLeave) {
  for (const HerschelBulkley& law : kLaws) {
    StokesFlowSolver solver(channel_mesh(), shear_law(law), channel_settings());
    const StokesResult r = solver.run({.velocity = {{0, developed(law)}, {2, zero}, {3, zero}},
                                       .straight_outflow = {1},
                                       .characteristic_rate = law.rate(G * H),
                                       .pressure_boundary = 0,
                                       .probes = {Point<2>(length, 0.0)}});
    // The inlet's mean pressure is the drop (p = 0 at the outlet); tolerances
    // as in the test above.
    EXPECT_NEAR(r.value.mean_pressure / (G * length), 1.0, 5e-3) << law.yield_stress;
    EXPECT_NEAR(r.value.dissipation / (G * exact::flow_rate(law, channel) * length), 1.0, 1e-3)
        << law.yield_stress;
    // The centreline speed at the outlet itself.
    EXPECT_NEAR(r.value.probes[0][0] / exact::velocity(law, channel, 0.0), 1.0, 1e-3)
        << law.yield_stress;
  }
}

}  // namespace
}  // namespace softglass::macro::fe
