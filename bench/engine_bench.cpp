// engine_bench: throughput and memory of the particle engine on a fixed amount
// of work, for the peer comparison (bench/lammps_comparison.sh) and the scaling
// study (bench/scaling.sh).
//
// A packing of `--base` particles is made and relaxed, then tiled k×k×k times
// (`--tile k`): a tiling of a force-balanced periodic packing is itself a
// force-balanced packing of the larger cell at the same φ, so large N costs no
// minimisation. The sheared dynamics then runs for `--steps` steps of fixed
// strain `--strain-per-step` (the step the peer takes), and only that part is
// timed. Output: one `key value` per line.
#include <fmt/format.h>
#include <omp.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <fstream>
#include <limits>
#include <string>

#include "micro/dynamics/integrator.h"
#include "micro/packing/packing.h"

using namespace softglass::micro;

namespace {

// Peak resident memory of this process (kB → bytes), from /proc.
double peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb;
      status >> kb;
      return kb * 1024.0;
    }
  }
  return 0.0;
}

Packing tile(const Packing& base, int k) {
  const double side = base.box.side();
  Particles tiled;
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      for (int c = 0; c < k; ++c)
        for (std::size_t i = 0; i < base.particles.size(); ++i) {
          tiled.position.push_back(base.particles.position[i] + side * Vec3(a, b, c));
          tiled.radius.push_back(base.particles.radius[i]);
        }
  Packing out{Particles(std::move(tiled.position), std::move(tiled.radius)),
              LeesEdwardsBox(k * side), base.report};
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"engine_bench: particle-steps per second and memory per particle"};
  PackingSpec spec;
  spec.radii.shape = "uniform";  // as the LAMMPS peer input: diameters 0.83 … 1.17
  std::string law_name = "hertz";
  int tile_factor = 1, steps = 2000, threads = 1;
  double strain_per_step = 2e-6, gamma_tilde = 1e-4;
  bool ehd = false;
  app.add_option("--base", spec.particles, "particles in the relaxed base packing");
  app.add_option("--tile", tile_factor, "tile the base packing k×k×k times");
  app.add_option("--phi", spec.volume_fraction, "volume fraction");
  app.add_option("--skin", spec.skin, "neighbour skin (units of R)");
  app.add_option("--law", law_name, "contact law");
  app.add_option("--steps", steps, "timed steps");
  app.add_option("--strain-per-step", strain_per_step, "fixed step (strain)");
  app.add_option("--gamma-tilde", gamma_tilde, "dimensionless shear rate");
  app.add_option("--threads", threads, "OpenMP threads");
  app.add_option("--seed", spec.seed, "packing seed");
  app.add_flag("--ehd", ehd, "include the EHD drag");
  CLI11_PARSE(app, argc, argv);
  omp_set_num_threads(threads);

  std::shared_ptr<const ContactLaw> law = make_contact_law({law_name, {}});
  const Packing packing = tile(make_packing(spec, law), tile_factor);
  const std::size_t n = packing.particles.size();

  ShearModel model;
  model.gamma_tilde = gamma_tilde;
  model.drag.enabled = ehd;
  OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model);
  IntegratorSpec integrator_spec{.name = "euler"};
  integrator_spec.max_step = strain_per_step;
  integrator_spec.tolerance = 0.1;  // the fixed step decides; no rejections
  const auto integrator = make_integrator(integrator_spec);
  // A run samples the stress every 0.01 strain, i.e. every 5000 steps of 2e-6 (as
  // the peer's thermo output); the timed steps are between samples.
  flow.sample_stress_from(std::numeric_limits<double>::infinity());
  flow.evaluate();
  integrator->step(flow, strain_per_step);  // warm up: first evaluation, buffers

  const std::size_t builds_before = flow.system().neighbours().builds();
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) integrator->step(flow, strain_per_step);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const double evaluations =
      static_cast<double>(integrator->stats().accepted + integrator->stats().rejected - 1);
  fmt::print("particles {}\n", n);
  fmt::print("threads {}\n", threads);
  fmt::print("steps {}\n", steps);
  fmt::print("rejected_steps {}\n", integrator->stats().rejected);
  fmt::print("neighbour_builds {}\n", flow.system().neighbours().builds() - builds_before);
  fmt::print("neighbours_per_particle {:.3f}\n",
             static_cast<double>(flow.system().neighbours().pair_count()) / static_cast<double>(n));
  fmt::print("contacts_per_particle {:.3f}\n",
             2.0 * static_cast<double>(flow.contact_count()) / static_cast<double>(n));
  fmt::print("seconds {:.4f}\n", seconds);
  fmt::print("particle_steps_per_second {:.4e}\n", static_cast<double>(n) * steps / seconds);
  fmt::print("evaluations_per_step {:.3f}\n", evaluations / steps);
  fmt::print("ns_per_particle_step {:.2f}\n", 1e9 * seconds / (static_cast<double>(n) * steps));
  fmt::print("engine_bytes_per_particle {:.1f}\n",
             static_cast<double>(flow.system().memory_bytes()) / static_cast<double>(n));
  fmt::print("peak_rss_bytes_per_particle {:.1f}\n",
             peak_resident_bytes() / static_cast<double>(n));
  return 0;
}
