// ehd_lagging: what lagging the EHD velocities costs in accuracy.
//
// Along an implicit trajectory (velocities solved to the default tolerance at
// every step), each step also computes the velocities the lagged scheme would
// use — one sweep ζ v = F^e + F^EHD(v_prev) with the previous step's velocities —
// and records their error against the solved ones, relative to the velocity
// scale max|v|. Then a run with `coupling = lagged` from the same packing gives
// the stresses to compare. Output: `key value` lines.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>

#include "micro/dynamics/integrator.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"

using namespace softglass::micro;

int main(int argc, char** argv) {
  CLI::App app{"ehd_lagging: error of lagging the EHD velocities"};
  PackingSpec spec;
  double gamma_tilde = 1e-4, strain = 2.0, run_strain = 20.0;
  app.add_option("--particles", spec.particles);
  app.add_option("--phi", spec.volume_fraction);
  app.add_option("--gamma-tilde", gamma_tilde);
  app.add_option("--strain", strain, "strain over which lagging errors are recorded");
  app.add_option("--run-strain", run_strain, "strain of the implicit and lagged runs (0: skip)");
  CLI11_PARSE(app, argc, argv);

  std::shared_ptr<const ContactLaw> law = make_contact_law({});
  const Packing packing = make_packing(spec, law);
  ShearModel model;
  model.gamma_tilde = gamma_tilde;

  // 1. Velocity error of one lagged sweep, step by step.
  {
    OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model);
    ShearModel lagged_model = model;
    lagged_model.drag.coupling = DragCoupling::lagged;
    EhdDrag lagged(lagged_model.drag);
    const auto integrator = make_integrator({.name = "euler"});
    flow.sample_stress_from(1e300);
    flow.evaluate();
    double worst = 0.0, sum2 = 0.0;
    std::size_t steps = 0;
    std::vector<double> friction;
    while (flow.strain() < strain) {
      std::vector<Vec3> previous(flow.velocities().begin(), flow.velocities().end());
      const std::size_t builds = flow.system().neighbours().builds();
      integrator->step(flow, strain - flow.strain());
      // A list build reorders the particles: skip those (rare) steps.
      if (flow.system().neighbours().builds() != builds) continue;
      const ContactField& field = flow.system().forces();
      friction.resize(previous.size());
      for (std::size_t a = 0; a < friction.size(); ++a)
        friction[a] = model.friction(flow.system().particles().radius[a]);
      std::vector<Vec3> v = previous;
      lagged.solve(field.contacts, gamma_tilde, 1.0, friction, field.force, v);
      double scale = 1.0, error = 0.0;
      for (std::size_t a = 0; a < v.size(); ++a) {
        scale = std::max(scale, flow.velocities()[a].norm());
        error = std::max(error, (v[a] - flow.velocities()[a]).norm());
      }
      worst = std::max(worst, error / scale);
      sum2 += (error / scale) * (error / scale);
      ++steps;
    }
    fmt::print("gamma_tilde {:.1e}\n", gamma_tilde);
    fmt::print("lagged_velocity_error_max {:.3e}\n", worst);
    fmt::print("lagged_velocity_error_rms {:.3e}\n",
               std::sqrt(sum2 / double(std::max<std::size_t>(steps, 1))));
    fmt::print("steps {}\n", steps);
  }

  // 2. Stresses of full runs, implicit and lagged, from the same packing.
  if (run_strain > 0) {
    ShearProtocol protocol;
    protocol.min_strain = protocol.max_strain = run_strain;
    protocol.min_stationary_strain = std::min(5.0, run_strain / 2);
    for (DragCoupling coupling : {DragCoupling::implicit, DragCoupling::lagged}) {
      ShearModel m = model;
      m.drag.coupling = coupling;
      OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), m);
      const auto integrator = make_integrator({.name = "euler"});
      try {
        const ShearResult r = run_shear(flow, *integrator, protocol);
        for (const char* q : {"sigma", "N1", "N2", "sigma_viscous"}) {
          const MeanEstimate& e = r.summary[q];
          fmt::print("{}_{} {:.5e} {:.2e}\n", to_string(coupling), q, e.mean, e.standard_error);
        }
        fmt::print("{}_seconds {:.1f}\n", to_string(coupling), r.seconds);
      } catch (const std::exception& e) {
        fmt::print("{}_failed \"{}\"\n", to_string(coupling), e.what());
      }
    }
  }
  return 0;
}
