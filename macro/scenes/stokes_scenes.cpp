// The scenes that need the full Stokes problem (fe/stokes_flow_solver.h).
//
// cavity:   the lid-driven square cavity of side L, lid speed U (the drive):
//           the Bingham benchmark of docs/macro.md (Bi = τ_y L/(μU)). Reports the
//           minimum of u_x on the vertical centreline and where it is.
// obstacle: a channel of height 0.41 D/0.1 with a cylinder of diameter D
//           (deal.II's channel_with_cylinder, the DFG benchmark's geometry,
//           scaled), mean inflow speed U (the drive) with a parabolic inflow
//           profile, straight outflow (StokesDrive). Reports the pressure drop inflow → outflow
//           and the drag and lift on the cylinder, per unit depth.
// contraction: a planar channel of height R h narrowing abruptly to h
//           (ratio R), each part 10 h long, mean inflow speed U (the drive),
//           parabolic inflow, straight outflow. Reports the pressure drop and the
//           yielded fraction (dead zones in the corners).
// cylinder: a cylinder of diameter D in a square box of side `box` D whose
//           walls move at U (the drive): the unbounded-flow benchmark of
//           docs/macro.md (Tokpavi et al. 2008) as the box grows. Reports the drag
//           per unit depth and C_D = F/(μU) with μ = K (Bingham).
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "macro/fe/stokes_flow_solver.h"
#include "macro/scenes/entries.h"
#include "macro/scenes/meshes.h"
#include "macro/scenes/scene.h"

namespace softglass::macro {

using dealii::ParameterHandler;
using dealii::Point;
using dealii::Tensor;
namespace Patterns = dealii::Patterns;

namespace {

// An unknown of the Stokes problem costs this many of a scalar scene's: three
// fields, a saddle point, continuation on the coarse mesh. Calibrated on the
// fast Bingham cavity against the scalar scenes' cost per unit of estimated
// work (docs/macro.md, "Cost of a sweep";
// bench/results/macro_cost_and_mpi-2026-11-21.md).
constexpr double kStokesRelativeCost = 30.0;

// Centreline samples of the cavity: the minimum is located to L/kSamples.
constexpr int kSamples = 400;

// Every Stokes scene reports one quantity with its discretisation and
// regularisation error estimates, then columns of its own, then the yielded
// fraction and the cost.
std::vector<Column> report_columns(const Column& value, const std::vector<Column>& own) {
  std::vector<Column> c = {value,
                           {value.name + "_discretisation_error", value.unit},
                           {value.name + "_regularisation_error", value.unit}};
  c.insert(c.end(), own.begin(), own.end());
  c.insert(c.end(), {{"yielded_fraction", "1"},
                     {"cells", "1"},
                     {"dofs", "1"},
                     {"iterations", "1"},
                     {"wall_time", "s"}});
  return c;
}

SceneResult report(const fe::StokesResult& r, const Estimate& main,
                   const std::vector<double>& own) {
  return {
      .quantity = MainQuantity::own,
      .main = main,
      .own = own,
      .yielded_fraction = r.value.yielded_fraction,
      .cost = {
          .cells = r.cells, .dofs = r.dofs, .iterations = r.iterations, .wall_time = r.wall_time}};
}

// A quantity of the outputs: its error estimates are its change over the last
// refinement and (value at 10ε − value at ε)/9 on the first mesh.
Estimate estimate(const fe::StokesResult& r,
                  const std::function<double(const fe::StokesOutputs&)>& quantity) {
  return {
      .value = quantity(r.value),
      .discretisation_error = std::abs(quantity(r.value) - quantity(r.coarse)),
      .regularisation_error = std::abs(quantity(r.first_mesh) - quantity(r.at_ten_epsilon)) / 9.0};
}

double mean_pressure(const fe::StokesOutputs& o) {
  return o.mean_pressure;
}
double drag(const fe::StokesOutputs& o) {
  return o.force[0];
}

// What the four scenes share: the solver on their mesh, the mesh's extent and
// the fields. Each derives its characteristic rate from its drive, and solves
// with it (characteristic_rate is what the input check sees).
class StokesScene : public Scene {
 public:
  StokesScene(const dealii::Triangulation<2>& mesh, std::shared_ptr<const ShearLaw> law,
              const fe::SolverSettings& settings)
      : solver_(mesh, std::move(law), settings), extent_(meshes::extent(mesh)) {
    extent_.relative_cost = kStokesRelativeCost;
  }
  MeshExtent mesh_extent() const override { return extent_; }
  void write_vtu(const std::filesystem::path& file) const override { solver_.output_results(file); }

 protected:
  fe::StokesFlowSolver solver_;

 private:
  MeshExtent extent_;
};

class Cavity final : public StokesScene {
 public:
  Cavity(double side, unsigned cells, std::shared_ptr<const ShearLaw> law,
         const fe::SolverSettings& settings)
      : StokesScene(mesh(side, cells), law, settings), side_(side), centreline_(centreline(side)) {}

  std::string description() const override {
    return fmt::format("lid-driven cavity, side {} m: Stokes (u, p), Taylor-Hood Q2-Q1", side_);
  }
  Column drive() const override { return {"lid_speed", "m/s"}; }
  std::vector<Column> columns() const override {
    return report_columns({"min_centreline_u", "m/s"}, {{"y_at_min_over_side", "1"}});
  }
  SceneResult solve(double lid) override {
    // No slip on walls (ids 0, 1, 2) after the lid (3), so the top corners
    // belong to the walls.
    const auto zero = [](const Point<2>&) { return Tensor<1, 2>(); };
    const auto moving = [lid](const Point<2>&) { return Tensor<1, 2>({lid, 0.0}); };
    const auto r = solver_.run({.velocity = {{3, moving}, {0, zero}, {1, zero}, {2, zero}},
                                .characteristic_rate = characteristic_rate(lid),
                                .probes = centreline_});
    // The minimum on each mesh: its change over the last refinement and
    // (at 10ε − at ε)/9 on the first mesh are its error estimates.
    const auto u_min = [this](const fe::StokesOutputs& o) { return centreline_minimum(o).first; };
    return report(r, estimate(r, u_min), {centreline_minimum(r.value).second / side_});
  }
  double characteristic_rate(double lid) const override { return lid / side_; }

 private:
  static dealii::Triangulation<2> mesh(double side, unsigned cells) {
    dealii::Triangulation<2> t;
    dealii::GridGenerator::subdivided_hyper_rectangle(t, {cells, cells}, Point<2>(0, 0),
                                                      Point<2>(side, side), true);
    return t;
  }
  static std::vector<Point<2>> centreline(double side) {
    std::vector<Point<2>> points;
    for (int k = 1; k < kSamples; ++k) points.emplace_back(0.5 * side, side * k / kSamples);
    return points;
  }
  // The minimum of u_x along the centreline and its height: the smallest
  // probe and the vertex of the parabola through it and its neighbours (the
  // probes' spacing alone would bias the minimum by ½u''Δy², ~1e-5 here).
  std::pair<double, double> centreline_minimum(const fe::StokesOutputs& o) const {
    std::size_t k = 0;
    for (std::size_t j = 1; j < o.probes.size(); ++j)
      if (o.probes[j][0] < o.probes[k][0]) k = j;
    if (k == 0 || k + 1 == o.probes.size()) return {o.probes[k][0], centreline_[k][1]};
    const double below = o.probes[k - 1][0], at = o.probes[k][0], above = o.probes[k + 1][0];
    const double shift = 0.5 * (below - above) / (below - 2.0 * at + above);
    const double spacing = centreline_[k + 1][1] - centreline_[k][1];
    return {at - 0.25 * (below - above) * shift, centreline_[k][1] + shift * spacing};
  }

  double side_;
  std::vector<Point<2>> centreline_;
};

class Obstacle final : public StokesScene {
 public:
  Obstacle(double diameter, std::shared_ptr<const ShearLaw> law, const fe::SolverSettings& settings)
      : StokesScene(mesh(diameter), law, settings), diameter_(diameter), height_(4.1 * diameter) {}

  std::string description() const override {
    return fmt::format(
        "channel of height {} m with a cylinder of diameter {} m (DFG geometry): Stokes (u, p), "
        "Taylor-Hood Q2-Q1",
        height_, diameter_);
  }
  Column drive() const override { return {"mean_inflow_speed", "m/s"}; }
  std::vector<Column> columns() const override {
    return report_columns({"pressure_drop", "Pa"},
                          {{"drag_per_depth", "N/m"}, {"lift_per_depth", "N/m"}});
  }
  SceneResult solve(double speed) override {
    const double H = height_;
    // Parabolic inflow with mean speed U: 6U y(H − y)/H².
    const auto inflow = [speed, H](const Point<2>& p) {
      return Tensor<1, 2>({6.0 * speed * p[1] * (H - p[1]) / (H * H), 0.0});
    };
    const auto zero = [](const Point<2>&) { return Tensor<1, 2>(); };
    const auto r = solver_.run({.velocity = {{0, inflow}, {2, zero}, {3, zero}},
                                .straight_outflow = {1},
                                .characteristic_rate = characteristic_rate(speed),
                                .force_boundary = 2,
                                .pressure_boundary = 0});
    return report(r, estimate(r, mean_pressure), {r.value.force[0], r.value.force[1]});
  }
  // The Newtonian wall rate of the parabolic inflow, 6U/H.
  double characteristic_rate(double speed) const override { return 6.0 * speed / height_; }

 private:
  // deal.II's DFG channel (D = 0.1) scaled by D/0.1, the cylinder's polar
  // manifold rebuilt about the scaled centre. The transfinite manifold of the
  // cells around it is dropped (flat): it is bound to the triangulation it
  // was initialised on, and the solver works on copies.
  static dealii::Triangulation<2> mesh(double diameter) {
    dealii::Triangulation<2> t;
    dealii::GridGenerator::channel_with_cylinder(t, 0.03, 2, 2.0, true);
    const double s = diameter / 0.1;
    dealii::GridTools::scale(s, t);
    t.set_manifold(0, dealii::PolarManifold<2>(Point<2>(0.2 * s, 0.2 * s)));
    t.reset_manifold(1);
    return t;
  }

  double diameter_, height_;
};

class Cylinder final : public StokesScene {
 public:
  Cylinder(double diameter, double box, std::shared_ptr<const ShearLaw> law,
           const fe::SolverSettings& settings)
      : StokesScene(mesh(diameter, box), law, settings),
        diameter_(diameter),
        box_(box),
        viscosity_(law->excess_stress(1.0)) {}

  std::string description() const override {
    return fmt::format(
        "cylinder of diameter {} m in a square box of side {} D, walls moving at U: Stokes (u, p), "
        "Taylor-Hood Q2-Q1",
        diameter_, box_);
  }
  Column drive() const override { return {"speed", "m/s"}; }
  std::vector<Column> columns() const override {
    return report_columns({"drag_per_depth", "N/m"}, {{"drag_coefficient_F_over_KU", "1"},
                                                      {"drag_from_surface_traction", "N/m"}});
  }
  // The drag from the power balance: the walls (moving at U) do work F U on
  // the material, all dissipated, while the cylinder (at rest) does none — so
  // F = ∫ τ:D dA / U, which converges at twice the rate of the surface
  // traction ∫ σn ds (like the torques of the rotational scenes). The traction
  // is reported beside it: their difference is a check of both.
  SceneResult solve(double speed) override {
    const auto uniform = [speed](const Point<2>&) { return Tensor<1, 2>({speed, 0.0}); };
    const auto zero = [](const Point<2>&) { return Tensor<1, 2>(); };
    const auto r = solver_.run(
        {.velocity = {{0, uniform}, {1, uniform}, {2, uniform}, {3, uniform}, {4, zero}},
         .characteristic_rate = characteristic_rate(speed),
         .force_boundary = 4});
    const auto power_drag = [speed](const fe::StokesOutputs& o) { return o.dissipation / speed; };
    return report(r, estimate(r, power_drag),
                  {power_drag(r.value) / (viscosity_ * speed), drag(r.value)});
  }
  double characteristic_rate(double speed) const override { return speed / diameter_; }

 private:
  // deal.II's plate with a hole: the hole (id 4, polar manifold) in a square
  // of side 3D (transfinite manifold, dropped as for the obstacle), padded to
  // the box; then two rings of refinement towards the cylinder.
  static dealii::Triangulation<2> mesh(double diameter, double box) {
    dealii::Triangulation<2> t;
    const double pad = 0.5 * (box - 3.0) * diameter;
    dealii::GridGenerator::plate_with_a_hole(t, 0.5 * diameter, 1.5 * diameter, pad, pad, pad, pad,
                                             Point<2>(), 0, 1, 1.0, 2, true);
    t.reset_manifold(1);
    return t;
  }

  double diameter_, box_;
  double viscosity_;  ///< K = Δ(1 1/s), the consistency of a Herschel–Bulkley law
};

class Contraction final : public StokesScene {
 public:
  Contraction(double height, unsigned ratio, std::shared_ptr<const ShearLaw> law,
              const fe::SolverSettings& settings)
      : StokesScene(mesh(height, ratio), law, settings), h_(height), ratio_(ratio) {}

  std::string description() const override {
    return fmt::format(
        "planar {}:1 contraction, downstream height {} m, 10 heights each side: Stokes (u, p), "
        "Taylor-Hood Q2-Q1",
        ratio_, h_);
  }
  Column drive() const override { return {"mean_inflow_speed", "m/s"}; }
  std::vector<Column> columns() const override {
    return report_columns({"pressure_drop", "Pa"}, {{"flow_rate_per_depth", "m^2/s"}});
  }
  SceneResult solve(double speed) override {
    const double H = ratio_ * h_;
    const auto inflow = [speed, H](const Point<2>& p) {
      return Tensor<1, 2>({6.0 * speed * p[1] * (H - p[1]) / (H * H), 0.0});
    };
    const auto zero = [](const Point<2>&) { return Tensor<1, 2>(); };
    const auto r = solver_.run({.velocity = {{0, inflow}, {2, zero}},
                                .straight_outflow = {1},
                                .characteristic_rate = characteristic_rate(speed),
                                .pressure_boundary = 0});
    return report(r, estimate(r, mean_pressure), {speed * H});
  }
  // The Newtonian wall rate downstream, 6 U_down/h with U_down = R U.
  double characteristic_rate(double speed) const override { return 6.0 * ratio_ * speed / h_; }

 private:
  // Square cells of side h/2 on [0, 20h] × [0, R h]; downstream (x > 10h)
  // only the centred band of height h is kept. Inflow id 0, outflow 1, walls 2.
  static dealii::Triangulation<2> mesh(double h, unsigned ratio) {
    const double H = ratio * h, L = 10.0 * h;
    dealii::Triangulation<2> box, t;
    dealii::GridGenerator::subdivided_hyper_rectangle(box, {40u, 2 * ratio}, Point<2>(0.0, 0.0),
                                                      Point<2>(2.0 * L, H));
    std::set<dealii::Triangulation<2>::active_cell_iterator> removed;
    for (const auto& c : box.active_cell_iterators()) {
      const Point<2> x = c->center();
      if (x[0] > L && std::abs(x[1] - 0.5 * H) > 0.5 * h) removed.insert(c);
    }
    dealii::GridGenerator::create_triangulation_with_removed_cells(box, removed, t);
    const double tol = 1e-9 * H;
    for (const auto& face : t.active_face_iterators()) {
      if (!face->at_boundary()) continue;
      const double x = face->center()[0];
      face->set_boundary_id(x < tol ? 0 : (std::abs(x - 2.0 * L) < tol ? 1 : 2));
    }
    return t;
  }

  double h_;
  unsigned ratio_;
};

}  // namespace

void declare_cavity(ParameterHandler& prm) {
  prm.enter_subsection("cavity");
  prm.declare_entry("side", "1", Patterns::Double(), "L [m], > 0");
  prm.declare_entry("cells", "16", Patterns::Integer(2, 1000), "cells per side (coarse mesh)");
  prm.leave_subsection();
}

void declare_obstacle(ParameterHandler& prm) {
  prm.enter_subsection("obstacle");
  prm.declare_entry("diameter", "0.01", Patterns::Double(),
                    "D [m], > 0: channel 2.2 D/0.1 long and 0.41 D/0.1 high");
  prm.leave_subsection();
}

void declare_contraction(ParameterHandler& prm) {
  prm.enter_subsection("contraction");
  prm.declare_entry("height", "0.005", Patterns::Double(), "h [m], the downstream height, > 0");
  prm.declare_entry("ratio", "4", Patterns::Integer(2, 20), "upstream height / h");
  prm.leave_subsection();
}

void declare_cylinder(ParameterHandler& prm) {
  prm.enter_subsection("cylinder");
  prm.declare_entry("diameter", "0.01", Patterns::Double(), "D [m], > 0");
  prm.declare_entry("box", "40", Patterns::Double(), "side of the square box in diameters, > 4");
  prm.leave_subsection();
}

std::unique_ptr<Scene> make_cylinder(ParameterHandler& prm, const Material& material,
                                     const fe::SolverSettings& settings) {
  prm.enter_subsection("cylinder");
  const double d = entries::positive(prm, "cylinder", "diameter", "m");
  const double box = entries::between(prm, "cylinder", "box", "1", 4.0, 1e4);
  prm.leave_subsection();
  return std::make_unique<Cylinder>(d, box, material.shear, settings);
}

std::unique_ptr<Scene> make_contraction(ParameterHandler& prm, const Material& material,
                                        const fe::SolverSettings& settings) {
  prm.enter_subsection("contraction");
  const double h = entries::positive(prm, "contraction", "height", "m");
  const unsigned ratio = prm.get_integer("ratio");
  prm.leave_subsection();
  return std::make_unique<Contraction>(h, ratio, material.shear, settings);
}

std::unique_ptr<Scene> make_cavity(ParameterHandler& prm, const Material& material,
                                   const fe::SolverSettings& settings) {
  prm.enter_subsection("cavity");
  const double side = entries::positive(prm, "cavity", "side", "m");
  const unsigned cells = prm.get_integer("cells");
  prm.leave_subsection();
  return std::make_unique<Cavity>(side, cells, material.shear, settings);
}

std::unique_ptr<Scene> make_obstacle(ParameterHandler& prm, const Material& material,
                                     const fe::SolverSettings& settings) {
  prm.enter_subsection("obstacle");
  const double d = entries::positive(prm, "obstacle", "diameter", "m");
  prm.leave_subsection();
  return std::make_unique<Obstacle>(d, material.shear, settings);
}

SceneEntry cavity_scene() {
  return {{"cavity",
           "lid-driven square cavity (Stokes)",
           {},
           [](const SceneSpec& s) { return make_cavity(s.prm, s.material, s.settings); }},
          declare_cavity};
}

SceneEntry obstacle_scene() {
  return {{"obstacle",
           "channel flow past a cylinder (Stokes, DFG geometry)",
           {},
           [](const SceneSpec& s) { return make_obstacle(s.prm, s.material, s.settings); }},
          declare_obstacle};
}

SceneEntry contraction_scene() {
  return {{"contraction",
           "planar abrupt contraction (Stokes)",
           {},
           [](const SceneSpec& s) { return make_contraction(s.prm, s.material, s.settings); }},
          declare_contraction};
}

SceneEntry cylinder_scene() {
  return {{"cylinder",
           "a cylinder moving through a large box (Stokes)",
           {},
           [](const SceneSpec& s) { return make_cylinder(s.prm, s.material, s.settings); }},
          declare_cylinder};
}

}  // namespace softglass::macro
