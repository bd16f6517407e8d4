#include "macro/scenes/reduced_scene.h"

#include "macro/scenes/meshes.h"

namespace softglass::macro {

namespace {

// The extent of the section, its volume that of the body it stands for
// (weighted by ρ = r on axisymmetric sections, times the measure factor).
template <int dim>
MeshExtent body_extent(const dealii::Triangulation<dim>& mesh, const fe::SectionWeights& w) {
  MeshExtent e = meshes::extent(mesh);
  e.volume = 0.0;
  for (const auto& cell : mesh.active_cell_iterators())
    e.volume += cell->measure() * w.rho(cell->center()[0]);
  e.volume *= w.measure_factor;
  return e;
}

template <int dim>
class ReducedScene final : public Scene {
 public:
  ReducedScene(const dealii::Triangulation<dim>& mesh, ReducedSceneSpec<dim> spec,
               std::shared_ptr<const ShearLaw> law, const fe::SolverSettings& settings)
      : spec_(std::move(spec)),
        extent_(body_extent(mesh, spec_.weights)),
        solver_(mesh, spec_.mapping_degree, spec_.weights, std::move(law), spec_.slip, settings) {}

  std::string description() const override { return spec_.description; }

  Column drive() const override {
    return spec_.kind == DriveKind::rotation ? Column{"rotation_rate", "rad/s"}
                                             : Column{"pressure_gradient", "Pa/m"};
  }

  std::vector<Column> columns() const override {
    const bool rotation = spec_.kind == DriveKind::rotation;
    const std::string name = rotation ? "torque" : "flow_rate";
    const std::string unit = rotation ? "N m" : spec_.flow_unit;
    std::vector<Column> c{{name, unit},
                          {name + "_discretisation_error", unit},
                          {name + "_regularisation_error", unit}};
    if (spec_.reference) {
      c.push_back({name + "_ideal_geometry", unit});
      c.push_back({kUndefinedWhereIdealIsZero, "1"});
    }
    if (rotation && spec_.normal_force.integrand) c.push_back({"normal_force", "N"});
    if (!rotation) c.push_back({"max_velocity", "m/s"});
    for (const Column& extra : std::vector<Column>{{"yielded_fraction", "1"},
                                                   {"cells", "1"},
                                                   {"dofs", "1"},
                                                   {"iterations", "1"},
                                                   {"wall_time", "s"}})
      c.push_back(extra);
    return c;
  }

  SceneResult solve(double drive) override {
    const fe::PointResult r = solver_.run(spec_.drive(drive), spec_.normal_force);
    const bool rotation = spec_.kind == DriveKind::rotation;
    // Torque from the dissipation: T Ω = ∫ τ γ̇ dV + ∫ σ_w V_s dA over slip
    // walls (the discrete reaction of the rotor with the test function ω_h/Ω,
    // which is 1 there and 0 on the stator; with slip walls, the power balance
    // of scalar_problem.h); flow rate c∫ρu directly.
    const auto main = [&](const fe::Outputs& o) {
      return rotation ? o.dissipation / drive : o.flow;
    };
    SceneResult result{.quantity = rotation ? MainQuantity::torque : MainQuantity::flow_rate,
                       .main = {.value = main(r.value),
                                .discretisation_error = main(r.discretisation_error),
                                .regularisation_error = main(r.regularisation_error)},
                       .yielded_fraction = r.value.yielded_fraction,
                       .cost = {.cells = r.cells,
                                .dofs = r.dofs,
                                .iterations = r.iterations,
                                .wall_time = r.wall_time}};
    if (spec_.reference) result.ideal_geometry = spec_.reference(drive);
    if (rotation && spec_.normal_force.integrand) result.normal_force = r.value.boundary;
    if (!rotation) result.max_velocity = r.value.max_value;
    return result;
  }

  double characteristic_rate(double drive) const override {
    return spec_.drive(drive).characteristic_rate;
  }

  MeshExtent mesh_extent() const override { return extent_; }

  void write_vtu(const std::filesystem::path& file) const override { solver_.output_results(file); }

  std::optional<InstrumentConstants> instrument() const override { return spec_.instrument; }

 private:
  ReducedSceneSpec<dim> spec_;
  MeshExtent extent_;
  fe::ScalarFlowSolver<dim> solver_;
};

}  // namespace

template <int dim>
std::unique_ptr<Scene> make_reduced_scene(const dealii::Triangulation<dim>& mesh,
                                          ReducedSceneSpec<dim> spec, std::shared_ptr<const ShearLaw> law,
                                          const fe::SolverSettings& settings) {
  return std::make_unique<ReducedScene<dim>>(mesh, std::move(spec), std::move(law), settings);
}

template std::unique_ptr<Scene> make_reduced_scene(const dealii::Triangulation<1>&,
                                                   ReducedSceneSpec<1>, std::shared_ptr<const ShearLaw>,
                                                   const fe::SolverSettings&);
template std::unique_ptr<Scene> make_reduced_scene(const dealii::Triangulation<2>&,
                                                   ReducedSceneSpec<2>, std::shared_ptr<const ShearLaw>,
                                                   const fe::SolverSettings&);

double pressure_rate_scale(const ShearLaw& law, double wall_stress) {
  const double rate = law.rate(wall_stress);
  return rate > 0.0 ? rate : law.rate_at_excess(0.1 * wall_stress);
}

}  // namespace softglass::macro
