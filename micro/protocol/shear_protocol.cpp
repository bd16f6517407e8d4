#include "micro/protocol/shear_protocol.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/errors.h"
#include "micro/analysis/layering.h"
#include "micro/model/overdamped_shear.h"

namespace softglass::micro {

namespace {
// The observables whose precision decides when to stop.
constexpr const char* kStoppingObservables[] = {"sigma", "N1", "N2"};
// Largest |z| of drift_statistic for a stationary part (3 standard errors).
constexpr double kMaxDrift = 3.0;
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
      for (const char* part : {"", "_elastic", "_viscous", "_film"})
        n.push_back(std::string(base) + part);
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
                              : part == "film"    ? film[k]
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
  const double film = summary["sigma_film"].mean;
  summary.elastic_to_film = film != 0.0 ? summary["sigma_elastic"].mean / film : 0.0;
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
  rejected_error += more.rejected_error;
  rejected_list += more.rejected_list;
  rejected_solver += more.rejected_solver;
  drag_freezes += more.drag_freezes;
  minimiser += more.minimiser;
  if (more.steps > 0) {
    smallest_step = first ? more.smallest_step : std::min(smallest_step, more.smallest_step);
    largest_step = std::max(largest_step, more.largest_step);
  }
  return *this;
}

bool stops_after_sample(const TimeSeries& series, const ShearProtocol& protocol, bool check_due,
                        bool at_max_strain, ShearResult& result, double& worst,
                        const std::function<std::optional<std::string>()>& own_reason) {
  if (check_due) {
    result.summary = summarise(series, protocol.min_stationary_strain);
    worst = result.summary.worst_relative_error();
    if (meets_stopping_rule(result.summary, protocol)) {
      result.converged = true;
      result.stop_reason = converged_stop_reason(result.summary);
      return true;
    }
    if (own_reason) {
      if (std::optional<std::string> reason = own_reason()) {
        result.stop_reason = *reason;
        return true;
      }
    }
  }
  if (at_max_strain) {
    result.summary = summarise(series, protocol.min_stationary_strain);
    result.stop_reason = max_strain_stop_reason(result.summary, protocol);
    return true;
  }
  return false;
}

}  // namespace softglass::micro
