#include "micro/protocol/shear_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/errors.h"
#include "micro/analysis/layering.h"

namespace softglass::micro {

namespace {
// The observables whose precision decides when to stop.
constexpr const char* kStoppingObservables[] = {"sigma", "N1", "N2"};
// Largest |z| of drift_statistic for a stationary part (3 standard errors).
constexpr double kMaxDrift = 3.0;
// Strain over which S_y is averaged to decide that a sample has layered.
constexpr double kLayeringWindow = 2.0;
}  // namespace

void ShearProtocol::validate() const {
  require(sample_interval > 0.0 && sample_interval <= 0.5,
          fmt::format("sample interval = {} is outside (0, 0.5] (strain)", sample_interval));
  require(check_interval >= sample_interval,
          fmt::format("check interval = {} is below the sample interval {}", check_interval,
                      sample_interval));
  require(min_strain >= 0.0 && std::isfinite(min_strain),
          fmt::format("minimum strain = {} must be non-negative", min_strain));
  require(max_strain >= min_strain && max_strain <= 1e6,
          fmt::format("maximum strain = {} is outside [minimum strain = {}, 1e6]", max_strain,
                      min_strain));
  require(min_stationary_strain >= 20 * sample_interval,
          fmt::format("minimum stationary strain = {} holds fewer than 20 samples",
                      min_stationary_strain));
  require(snapshot_interval == 0.0 ||
              (snapshot_interval >= sample_interval && std::isfinite(snapshot_interval)),
          fmt::format("snapshot interval = {} must be 0 (none) or at least the sample interval {}",
                      snapshot_interval, sample_interval));
  require(target_relative_error > 0.0 && target_relative_error < 1.0,
          fmt::format("target relative error = {} is outside (0, 1)", target_relative_error));
}

const std::vector<std::string>& shear_observable_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const char* base : {"sigma", "N1", "N2", "pressure"})
      for (const char* part : {"", "_elastic", "_viscous"}) n.push_back(std::string(base) + part);
    return n;
  }();
  return names;
}

std::vector<double> TimeSeries::component(const std::string& observable) const {
  const auto underscore = observable.find('_');
  const std::string base = observable.substr(0, underscore);
  const std::string part = underscore == std::string::npos ? "" : observable.substr(underscore + 1);
  const auto value = [&](std::size_t k) -> double {
    const Eigen::Matrix3d s = part == "elastic"   ? elastic[k]
                              : part == "viscous" ? viscous[k]
                                                  : Eigen::Matrix3d(elastic[k] + viscous[k]);
    const ShearObservables o = observables(s);
    if (base == "sigma") return o.shear;
    if (base == "N1") return o.n1;
    if (base == "N2") return o.n2;
    if (base == "pressure") return o.pressure;
    throw std::invalid_argument("unknown observable " + observable);
  };
  std::vector<double> values(size());
  for (std::size_t k = 0; k < size(); ++k) values[k] = value(k);
  return values;
}

const MeanEstimate& find_estimate(const std::vector<ObservableEstimate>& list,
                                  const std::string& name) {
  for (const auto& o : list)
    if (o.name == name) return o.estimate;
  throw std::invalid_argument("no observable " + name);
}

const MeanEstimate& ShearSummary::operator[](const std::string& name) const {
  return find_estimate(observables, name);
}

bool ShearSummary::layered() const {
  return layering > kLayeredThreshold;
}

double ShearSummary::worst_relative_error() const {
  double worst = 0.0;
  for (const char* name : kStoppingObservables) {
    const MeanEstimate& e = (*this)[name];
    worst = std::max(worst, e.mean != 0.0 ? std::abs(e.standard_error / e.mean)
                                          : std::numeric_limits<double>::infinity());
  }
  return worst;
}

ShearSummary summarise(const TimeSeries& series, double min_stationary_strain) {
  ShearSummary summary;
  if (series.size() < 2) return summary;
  const double interval = series.strain[1] - series.strain[0];
  const auto min_samples = static_cast<std::size_t>(std::ceil(min_stationary_strain / interval));

  const auto& names = shear_observable_names();
  std::vector<std::vector<double>> values;
  for (const auto& name : names) values.push_back(series.component(name));
  std::vector<std::span<const double>> deciding;
  for (const char* name : kStoppingObservables) {
    deciding.emplace_back(values[std::find(names.begin(), names.end(), name) - names.begin()]);
  }

  const SteadyStateAnalysis analysis = analyse_steady_state(deciding, min_samples);
  const std::size_t first = analysis.transient_samples;
  summary.transient_strain = series.strain[first] - series.strain.front();
  summary.averaged_strain = series.strain.back() - series.strain[first];
  summary.transient_resolved = !analysis.transient_unresolved && analysis.enough_samples;

  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::span<const double> stationary(values[k].data() + first, values[k].size() - first);
    summary.observables.push_back({names[k], block_average(stationary)});
  }
  const double viscous = summary["sigma_viscous"].mean;
  summary.elastic_to_viscous = viscous != 0.0 ? summary["sigma_elastic"].mean / viscous : 0.0;
  double z = 0.0, layering = 0.0;
  for (std::size_t k = first; k < series.size(); ++k) {
    z += series.coordination[k];
    layering += series.layering[k];
  }
  summary.coordination = z / static_cast<double>(series.size() - first);
  summary.layering = layering / static_cast<double>(series.size() - first);
  for (const auto& observable : deciding) {
    summary.drift = std::max(summary.drift, std::abs(drift_statistic(observable.subspan(first))));
  }
  return summary;
}

LeesEdwardsBox checkpointed_cell(const LeesEdwardsBox& box) {
  LeesEdwardsBox cell(box.side());
  cell.set_strain(box.strain());
  return cell;
}

bool meets_stopping_rule(const ShearSummary& summary, const ShearProtocol& protocol) {
  bool reliable = summary.transient_resolved && summary.drift <= kMaxDrift;
  for (const char* name : kStoppingObservables) reliable = reliable && summary[name].reliable;
  return reliable && summary.worst_relative_error() <= protocol.target_relative_error;
}

std::string converged_stop_reason(const ShearSummary& summary) {
  return fmt::format("stationary, relative standard errors ≤ {:.3g}",
                     summary.worst_relative_error());
}

std::string max_strain_stop_reason(const ShearSummary& summary, const ShearProtocol& protocol) {
  return fmt::format("maximum strain {} reached before the target error {} (worst {:.3g}){}{}",
                     protocol.max_strain, protocol.target_relative_error,
                     summary.worst_relative_error(),
                     summary.transient_resolved ? "" : "; the transient may not be over",
                     summary.drift <= kMaxDrift
                         ? ""
                         : fmt::format("; the stresses drift (|z| = {:.1f})", summary.drift));
}

ShearCounters& ShearCounters::operator+=(const ShearCounters& more) {
  const bool first = steps == 0;
  steps += more.steps;
  rejected_steps += more.rejected_steps;
  evaluations += more.evaluations;
  neighbour_builds += more.neighbour_builds;
  fixed_point_sweeps += more.fixed_point_sweeps;
  newton_iterations += more.newton_iterations;
  cg_iterations += more.cg_iterations;
  if (more.steps > 0) {
    smallest_step = first ? more.smallest_step : std::min(smallest_step, more.smallest_step);
    largest_step = std::max(largest_step, more.largest_step);
  }
  return *this;
}

ShearResult run_shear(OverdampedShear& flow, Integrator& given_integrator,
                      const ShearProtocol& protocol,
                      const std::function<void(const ShearProgress&)>& progress,
                      const ShearCheckpointing& checkpointing) {
  protocol.validate();
  if ((checkpointing.every_steps > 0 || checkpointing.resume_from) && !checkpointing.new_integrator)
    throw std::invalid_argument("run_shear: checkpoints need new_integrator");
  const auto clock_start = std::chrono::steady_clock::now();
  ShearResult result;
  TimeSeries& series = result.series;
  double start = flow.strain();
  double next_snapshot = 0.0;  // strain since the start
  double next_sample = start + protocol.sample_interval;
  double next_check = start + std::max(protocol.check_interval, protocol.min_strain);
  double worst = std::numeric_limits<double>::infinity();
  double seconds_before = 0.0;  // of the run before it was resumed

  // The counters of the current segment (since the start or the last
  // checkpoint) and of the finished segments.
  Integrator* integrator = &given_integrator;
  std::unique_ptr<Integrator> owned_integrator;
  ShearCounters finished;
  std::size_t builds_before = 0, evaluations_before = 0, accepted_before = 0, rejected_before = 0;
  ShearCounters solver;  // sweeps, Newton and CG iterations of this segment
  const auto segment = [&] {
    const IntegratorStats& stats = integrator->stats();
    ShearCounters c = solver;
    c.steps = stats.accepted - accepted_before;
    c.rejected_steps = stats.rejected - rejected_before;
    c.evaluations = flow.evaluations() - evaluations_before;
    c.neighbour_builds = flow.system().neighbours().builds() - builds_before;
    c.smallest_step = stats.smallest_step;
    c.largest_step = stats.largest_step;
    return c;
  };
  const auto begin_segment = [&] {
    builds_before = flow.system().neighbours().builds();
    evaluations_before = flow.evaluations();
    accepted_before = integrator->stats().accepted;
    rejected_before = integrator->stats().rejected;
    solver = {};
  };

  const auto record = [&] {
    const StressSample s = flow.stress();
    series.strain.push_back(flow.strain());
    series.elastic.push_back(s.elastic);
    series.viscous.push_back(s.viscous);
    series.coordination.push_back(2.0 * static_cast<double>(flow.contact_count()) /
                                  static_cast<double>(flow.system().size()));
    series.layering.push_back(
        gradient_layering(flow.system().particles().position, flow.system().box().side()).order);
    series.step.push_back(integrator->stats().last_step);
    // Snapshots on the samples nearest to each multiple of the snapshot interval.
    if (protocol.snapshot_interval > 0.0 &&
        flow.strain() - start >= next_snapshot - 1e-9 * protocol.sample_interval) {
      result.snapshots.push_back({flow.strain(), flow.system().wrapped_in_label_order().position});
      next_snapshot += protocol.snapshot_interval;
    }
  };
  // Steps between samples skip the stress (the sample lands exactly on its strain).
  const auto sample_at = [&](double strain) {
    flow.sample_stress_from(strain - 1e-9 * protocol.sample_interval);
  };

  // Starting afresh from a checkpoint: a new contact system built from the
  // stored particles, a new integrator, the first evaluation from the stored
  // velocities.
  const auto restart_from = [&](const ShearCheckpoint& c) {
    const std::shared_ptr<const ContactLaw> law = flow.system().shared_law();
    const double skin = flow.system().neighbours().skin();
    flow = OverdampedShear(ContactSystem(c.particles, c.box, law, skin), flow.model());
    owned_integrator = checkpointing.new_integrator();
    integrator = owned_integrator.get();
    start = c.start;
    next_sample = c.next_sample;
    next_check = c.next_check;
    next_snapshot = c.next_snapshot;
    worst = c.worst;
    begin_segment();
    sample_at(next_sample);
    flow.evaluate();
  };
  const auto checkpoint = [&] {
    finished += segment();
    ShearCheckpoint c{
        flow.system().particles(),
        checkpointed_cell(flow.system().box()),
        start,
        next_sample,
        next_check,
        next_snapshot,
        worst,
        series,
        result.snapshots,
        finished,
        seconds_before +
            std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count()};
    if (checkpointing.save) checkpointing.save(c);
    restart_from(c);
  };

  if (const ShearCheckpoint* resume = checkpointing.resume_from) {
    series = resume->series;
    result.snapshots = resume->snapshots;
    finished = resume->counters;
    seconds_before = resume->seconds;
    restart_from(*resume);
  } else {
    begin_segment();
    flow.sample_stress_from(-std::numeric_limits<double>::infinity());
    flow.evaluate();  // the first sample
    record();
    sample_at(next_sample);
  }

  for (;;) {
    if (checkpointing.every_steps > 0 &&
        integrator->stats().accepted - accepted_before >= checkpointing.every_steps)
      checkpoint();
    integrator->step(flow, next_sample - flow.strain());
    solver.fixed_point_sweeps += static_cast<std::size_t>(flow.last_solve().fixed_point_sweeps);
    solver.newton_iterations += static_cast<std::size_t>(flow.last_solve().newton_iterations);
    solver.cg_iterations += static_cast<std::size_t>(flow.last_solve().cg_iterations);
    if (flow.strain() < next_sample - 1e-9 * protocol.sample_interval) continue;

    record();
    next_sample += protocol.sample_interval;
    sample_at(next_sample);
    const double sheared = flow.strain() - start;
    if (flow.strain() >= next_check - 1e-9 * protocol.sample_interval) {
      next_check += protocol.check_interval;
      result.summary = summarise(series, protocol.min_stationary_strain);
      worst = result.summary.worst_relative_error();
      if (meets_stopping_rule(result.summary, protocol)) {
        result.converged = true;
        result.stop_reason = converged_stop_reason(result.summary);
        break;
      }
      // A sample that has layered is no longer a glass: stop, unconverged.
      const std::size_t window =
          std::min(series.size(),
                   static_cast<std::size_t>(std::ceil(kLayeringWindow / protocol.sample_interval)));
      double recent = 0.0;
      for (std::size_t k = series.size() - window; k < series.size(); ++k)
        recent += series.layering[k] / window;
      if (recent > kLayeredThreshold) {
        result.stop_reason = fmt::format(
            "the sample layered under shear (S_y = {:.0f} over the last {} strain, threshold "
            "{:.0f})",
            recent, kLayeringWindow, kLayeredThreshold);
        break;
      }
    }
    if (progress) progress({sheared, protocol.max_strain, worst});
    if (sheared >= protocol.max_strain - 1e-9 * protocol.sample_interval) {
      result.summary = summarise(series, protocol.min_stationary_strain);
      result.stop_reason = max_strain_stop_reason(result.summary, protocol);
      break;
    }
  }

  finished += segment();
  result.counters = finished;
  result.seconds =
      seconds_before +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

}  // namespace softglass::micro
