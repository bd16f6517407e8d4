#include "micro/protocol/wall_run.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/errors.h"

namespace softglass::micro {

void WallRunSpec::validate() const {
  require(std::isfinite(sample_interval) && sample_interval > 0.0 && sample_interval <= 1.0,
          fmt::format("walls: sample interval = {} is outside (0, 1]", sample_interval));
  require(std::isfinite(strain) && strain >= 20.0 * sample_interval && strain <= 1e4,
          fmt::format("walls: strain = {} is outside [20 × sample interval = {}, 1e4]", strain,
                      20.0 * sample_interval));
  sampling.validate();
}

WallRunResult run_wall_shear(OverdampedShear& flow, Integrator& integrator, const WallRunSpec& spec,
                             const std::function<void(double)>& progress) {
  spec.validate();
  if (!flow.system().walls().present())
    throw std::logic_error("run_wall_shear: the system has no walls");
  const bool contacts = flow.model().drag.enabled || flow.model().drag.stokes.has_pairs();
  require(contacts, "walls: a smooth wall takes shear only through its films: enable the EHD drag");
  const auto start = std::chrono::steady_clock::now();
  WallRunResult run;
  const double begin = flow.strain();
  double next = begin + spec.sample_interval;
  flow.sample_stress_from(next);
  while (next <= begin + spec.strain + 1e-9 * spec.sample_interval) {
    integrator.step(flow, next - flow.strain());
    ++run.steps;
    if (flow.strain() < next - 1e-9 * spec.sample_interval) continue;
    if (!flow.evaluated()) flow.evaluate();
    run.strain.push_back(flow.strain() - begin);
    run.samples.push_back(measure_wall_sample(flow, spec.sampling));
    next += spec.sample_interval;
    flow.sample_stress_from(next);
    if (progress) progress(flow.strain() - begin);
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::vector<std::string> wall_observable_names() {
  return {"wall_stress",   "wall_stress_lower", "wall_stress_upper", "bulk_stress",
          "bulk_stress_elastic", "balance",     "bulk_rate",         "slip_velocity",
          "normal_stress", "wall_contacts",     "load_per_contact"};
}

std::vector<double> wall_observable_series(const WallRunResult& run, const std::string& name) {
  std::vector<double> out;
  out.reserve(run.samples.size());
  for (const WallSample& s : run.samples) {
    const double contacts = 0.5 * (s.contacts_lower + s.contacts_upper);
    const double normal = 0.5 * (s.normal_stress_lower + s.normal_stress_upper);
    if (name == "wall_stress") out.push_back(0.5 * (s.wall_stress_lower + s.wall_stress_upper));
    else if (name == "wall_stress_lower") out.push_back(s.wall_stress_lower);
    else if (name == "wall_stress_upper") out.push_back(s.wall_stress_upper);
    else if (name == "bulk_stress") out.push_back(s.bulk_stress);
    else if (name == "bulk_stress_elastic") out.push_back(s.bulk_stress_elastic);
    else if (name == "balance") out.push_back(s.bulk_stress - s.reservoir_term);
    else if (name == "bulk_rate") out.push_back(s.bulk_rate);
    else if (name == "slip_velocity") out.push_back(s.slip_velocity);
    else if (name == "normal_stress") out.push_back(normal);
    else if (name == "wall_contacts") out.push_back(contacts);
    else if (name == "load_per_contact") out.push_back(contacts > 0.0 ? normal / contacts : 0.0);
    else throw std::invalid_argument(fmt::format("no wall observable '{}'", name));
  }
  return out;
}

WallRunSummary summarise_wall_run(const WallRunResult& run) {
  if (run.samples.size() < 5 * kMserMinBatches)
    throw std::invalid_argument(fmt::format("a wall run of {} samples is too short to analyse",
                                            run.samples.size()));
  const auto wall = wall_observable_series(run, "wall_stress");
  const auto bulk = wall_observable_series(run, "bulk_stress");
  const auto slip = wall_observable_series(run, "slip_velocity");
  const SteadyStateAnalysis analysis = analyse_steady_state({wall, bulk, slip}, 16);
  WallRunSummary summary;
  summary.transient_samples = analysis.transient_samples;
  summary.stationary_samples = analysis.stationary_samples;
  summary.converged = analysis.converged();
  const std::size_t from = analysis.transient_samples;
  for (const std::string& name : wall_observable_names()) {
    const auto series = wall_observable_series(run, name);
    summary.estimates.push_back(
        {name, block_average(std::span<const double>(series).subspan(from))});
  }
  const std::size_t bins = run.samples.front().profile.size();
  for (std::size_t b = 0; b < bins; ++b) {
    std::vector<double> u;
    for (std::size_t t = from; t < run.samples.size(); ++t)
      if (std::isfinite(run.samples[t].profile[b])) u.push_back(run.samples[t].profile[b]);
    const bool enough = u.size() >= kBlockingMinSamples;
    const MeanEstimate e = enough ? block_average(u) : MeanEstimate{};
    summary.profile.push_back(enough ? e.mean : std::nan(""));
    summary.profile_error.push_back(enough ? e.standard_error : std::nan(""));
  }
  return summary;
}

}  // namespace softglass::micro
