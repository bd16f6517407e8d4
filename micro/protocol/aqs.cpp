#include "micro/protocol/aqs.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "common/errors.h"
#include "micro/dynamics/incremental_minimiser.h"

namespace softglass::micro {

namespace {
// Non-affine move allowed for per minimisation before the list is rebuilt (R).
constexpr double kListMargin = 0.05;
// A margin no list is valid for: forces a rebuild where the system is.
constexpr double kForceRebuild = 1e6;
// A step that converges in this many Newton iterations was elastic.
constexpr int kElasticIterations = 6;
}  // namespace

void AqsSettings::validate() const {
  require(strain_step > 0.0 && strain_step <= kMaxAqsStrainStep,
          fmt::format("AQS strain step = {} is outside (0, {}]", strain_step, kMaxAqsStrainStep));
  require(strain >= 20 * strain_step,
          fmt::format("AQS strain = {} is shorter than 20 strain steps", strain));
  require(min_stationary_strain >= 20 * strain_step && min_stationary_strain <= strain,
          "AQS stationary window must span at least 20 steps and at most the run");
  require(relative_force > 0.0 && relative_force <= kMaxAqsForceTolerance,
          fmt::format("AQS force tolerance = {} is outside (0, {}]", relative_force,
                      kMaxAqsForceTolerance));
  require(max_iterations >= 1, "AQS needs at least one Newton iteration per step");
}

AqsResult run_aqs(ContactSystem& system, const AqsSettings& settings, const AqsObserver& observer) {
  settings.validate();
  const auto clock_start = std::chrono::steady_clock::now();
  IncrementalMinimiser minimiser({.relative_force = settings.relative_force,
                                  .absolute_force = 0.0,
                                  .loosen = false,
                                  .max_iterations = settings.max_iterations});
  AqsResult result;
  const FrozenDrag no_drag;
  const std::size_t n = system.size();
  auto& previous = system.particles().velocity;  // last step's u/Δγ; moves with reordering
  previous.assign(n, Vec3::Zero());
  std::vector<Vec3> u(n);
  std::vector<double> energies, all_energies;
  const double start = system.box().strain();
  const auto steps = static_cast<std::size_t>(std::llround(settings.strain / settings.strain_step));
  const double dg = settings.strain_step;
  double last_sigma = 0.0;
  bool elastic_before = true;

  for (std::size_t step = 1; step <= steps; ++step) {
    system.ensure_neighbours(kListMargin, system.box().strain() + dg);
    system.shear(dg);
    // The last step's displacement as the guess, unless it was a plastic event
    // (many iterations): then its rearrangement says nothing about this step.
    for (std::size_t a = 0; a < n; ++a)
      u[a] = elastic_before ? Vec3(dg * previous[a]) : Vec3::Zero();
    int iterations = 0;
    all_energies.clear();
    for (;;) {
      const IncrementalResult r =
          minimiser.minimise(system, {}, no_drag, 1.0, u, observer ? &energies : nullptr,
                             settings.max_iterations - iterations);
      iterations += r.iterations;
      if (observer) {
        const double offset = all_energies.empty() ? 0.0 : all_energies.back();
        for (std::size_t k = all_energies.empty() ? 0 : 1; k < energies.size(); ++k)
          all_energies.push_back(offset + energies[k]);
      }
      // The displacement of this pass is done (the system is at x⁰ + u); a
      // restart minimises from there, so it is not counted twice in the guess.
      for (std::size_t a = 0; a < n; ++a) previous[a] = u[a] / dg;
      if (!r.list_invalid) {
        if (!r.converged) ++result.unconverged_steps;
        break;
      }
      // A large rearrangement: rebuild the list where the system is and go on
      // minimising (Φ = E does not depend on the starting point).
      system.ensure_neighbours(kForceRebuild);
      std::fill(u.begin(), u.end(), Vec3::Zero());
      if (iterations >= settings.max_iterations) {
        ++result.unconverged_steps;
        break;
      }
    }
    if (observer) observer(all_energies);
    elastic_before = iterations <= kElasticIterations;
    // The minimiser's last evaluation is at this very point, with the energy
    // and the contacts: the virial is summed over those.
    const ContactField& field = system.current_forces({.energy = true, .contacts = true});
    const Eigen::Matrix3d sigma = -field.contacts.virial() / system.box().volume();
    result.series.strain.push_back(system.box().strain() - start);
    result.series.elastic.push_back(sigma);
    result.series.viscous.push_back(Eigen::Matrix3d::Zero());
    result.series.film.push_back(Eigen::Matrix3d::Zero());
    result.series.coordination.push_back(2.0 * double(field.contact_count) / double(n));
    result.series.layering.push_back(0.0);
    result.series.step.push_back(dg);
    result.energy.push_back(field.energy);
    const double s = sigma(1, 0);
    if (step > 1 && s < last_sigma) ++result.stress_drops;
    last_sigma = s;
    ++result.steps;
  }
  result.minimiser = minimiser.counters();
  result.summary = summarise(result.series, settings.min_stationary_strain);
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

AqsResult aqs_flow_curve_point(ContactSystem system, const AqsSettings& settings) {
  return run_aqs(system, settings);
}

}  // namespace softglass::micro
