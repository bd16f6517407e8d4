#include "micro/packing/packing.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <random>

#include "common/errors.h"

namespace softglass::micro {

void PackingSpec::validate() const {
  require(particles >= 2 && particles <= 50'000'000,
          fmt::format("number of particles = {} is outside [2, 5e7]", particles));
  require(std::isfinite(volume_fraction) && volume_fraction >= 0.64 && volume_fraction <= 0.95,
          fmt::format("volume fraction φ = {} is outside [0.64, 0.95] (soft glasses are compressed "
                      "beyond random close packing)",
                      volume_fraction));
  require(initial_volume_fraction >= 0.05 && initial_volume_fraction <= volume_fraction,
          fmt::format("initial volume fraction = {} is outside [0.05, φ = {}]",
                      initial_volume_fraction, volume_fraction));
  require(compression_step > 0.0 && compression_step <= 0.1,
          fmt::format("compression step = {} is outside (0, 0.1]", compression_step));
  require(stage_tolerance > 0.0 && stage_tolerance < 1.0,
          fmt::format("stage tolerance = {} is outside (0, 1)", stage_tolerance));
  require(stage_iterations >= 1, "stage iterations must be at least 1");
  require(skin > 0.0 && skin <= 2.0, fmt::format("neighbour skin = {} is outside (0, 2]", skin));
  radii.validate();
  relaxation.validate();
}

PackingReport describe_packing(ContactSystem& system) {
  const ContactField& field = system.compute_forces({.energy = true, .contacts = true});
  const ContactList& c = field.contacts;
  const std::size_t n = system.size();
  PackingReport r;
  r.particles = n;
  r.volume_fraction = system.occupied_volume_fraction();
  r.side = system.box().side();
  r.coordination = 2.0 * static_cast<double>(c.size()) / static_cast<double>(n);
  for (std::size_t k = 0; k < c.size(); ++k) {
    r.mean_deformation += c.deformation[k];
    r.max_deformation = std::max(r.max_deformation, c.deformation[k]);
  }
  if (c.size() > 0) r.mean_deformation /= static_cast<double>(c.size());
  r.pressure = field.virial.trace() / (3.0 * system.box().volume());
  r.energy_per_particle = field.energy / static_cast<double>(n);
  r.residual = force_residual(field);

  // Rattlers: fewer than d + 1 = 4 contacts among non-rattlers, removed until
  // none is left (a queue over the contact graph); Z of the remaining backbone.
  std::vector<std::vector<std::uint32_t>> adjacent(n);
  for (std::size_t k = 0; k < c.size(); ++k) {
    adjacent[c.i[k]].push_back(c.j[k]);
    adjacent[c.j[k]].push_back(c.i[k]);
  }
  std::vector<std::size_t> degree(n);
  std::vector<bool> rattler(n, false);
  std::vector<std::uint32_t> queue;
  for (std::size_t a = 0; a < n; ++a) {
    degree[a] = adjacent[a].size();
    if (degree[a] < 4) {
      rattler[a] = true;
      queue.push_back(static_cast<std::uint32_t>(a));
    }
  }
  while (!queue.empty()) {
    const std::uint32_t a = queue.back();
    queue.pop_back();
    for (const std::uint32_t b : adjacent[a]) {
      if (!rattler[b] && --degree[b] < 4) {
        rattler[b] = true;
        queue.push_back(b);
      }
    }
  }
  std::size_t backbone_contacts = 0;
  for (std::size_t k = 0; k < c.size(); ++k)
    backbone_contacts += !rattler[c.i[k]] && !rattler[c.j[k]];
  r.rattlers = static_cast<std::size_t>(std::count(rattler.begin(), rattler.end(), true));
  r.coordination_nonrattler = r.rattlers < n ? 2.0 * static_cast<double>(backbone_contacts) /
                                                   static_cast<double>(n - r.rattlers)
                                             : 0.0;
  return r;
}

Packing make_packing(const PackingSpec& spec, std::shared_ptr<const ContactLaw> law,
                     const std::function<void(double)>& progress) {
  spec.validate();
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> radii = sample_radii(spec.particles, spec.radii, spec.seed);

  // Random centres at φ₀; a second stream so that radii do not depend on placement.
  double particle_volume = 0.0;
  for (double r : radii) particle_volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double side = std::cbrt(particle_volume / spec.initial_volume_fraction);
  std::mt19937_64 rng(spec.seed ^ 0x9e3779b97f4a7c15ull);
  std::uniform_real_distribution<double> uniform(0.0, side);
  std::vector<Vec3> centres(spec.particles);
  for (Vec3& x : centres) x = Vec3(uniform(rng), uniform(rng), uniform(rng));

  ContactSystem system(Particles(std::move(centres), std::move(radii)), LeesEdwardsBox(side), law,
                       spec.skin);
  const std::size_t iterations = compress(system, spec, progress);
  return {system.wrapped_in_label_order(), system.box(), finish_report(system, spec, iterations, start)};
}

std::size_t compress(ContactSystem& system, const PackingSpec& spec,
                     const std::function<void(double)>& progress) {
  FireSettings stage = spec.relaxation;
  stage.force_tolerance = std::max(spec.stage_tolerance, spec.relaxation.force_tolerance);
  stage.max_iterations = spec.stage_iterations;
  std::size_t iterations = minimise_fire(system, stage).iterations;
  // Every length scales with the cell (walls included), so φ — of the cell or
  // of the slab between walls — goes like the inverse cube of the scale.
  double phi = spec.initial_volume_fraction;
  while (phi < spec.volume_fraction) {
    const double next = std::min(phi + spec.compression_step, spec.volume_fraction);
    system.rescale(std::cbrt(phi / next));
    phi = next;
    iterations +=
        minimise_fire(system, phi < spec.volume_fraction ? stage : spec.relaxation).iterations;
    if (progress) progress(phi);
  }
  if (spec.initial_volume_fraction == spec.volume_fraction) {
    iterations += minimise_fire(system, spec.relaxation).iterations;
  }
  return iterations;
}

PackingReport finish_report(ContactSystem& system, const PackingSpec& spec, std::size_t iterations,
                            std::chrono::steady_clock::time_point start) {
  PackingReport report = describe_packing(system);
  report.iterations = iterations;
  report.converged = report.residual <= spec.relaxation.force_tolerance;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace softglass::micro
