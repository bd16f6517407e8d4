#include "micro/io/oscillation_group.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "common/oscillation_columns.h"
#include "micro/io/h5_groups.h"
#include "micro/io/run_file.h"

namespace softglass::micro {

namespace {

void write_protocol(H5Group& g, const OscillationProtocol& p) {
  g.write_scalar("amplitude", p.amplitude, {"1", "strain amplitude gamma0"});
  g.write_scalar("frequency", p.frequency,
                 {"1", "reduced angular frequency omega~ = omega eta_s / E*"});
  g.write_scalar("peak_gamma_tilde", p.peak_gamma_tilde(),
                 {"1", "peak shear rate gamma0 omega~, the model's gamma~ (time unit 1/its rate)"});
  g.set_attribute("samples_per_cycle", static_cast<std::int64_t>(p.samples_per_cycle));
  g.set_attribute("min_cycles", static_cast<std::int64_t>(p.min_cycles));
  g.set_attribute("max_cycles", static_cast<std::int64_t>(p.max_cycles));
  g.set_attribute("min_periodic_cycles", static_cast<std::int64_t>(p.min_periodic_cycles));
  g.set_attribute("target_relative_error", p.target_relative_error);
}

// The series as a steady run's, plus each sample's time and rate.
void write_series(H5Group&& g, const TimeSeries& series, const OscillationProtocol& p) {
  std::vector<double> time(series.size()), rate(series.size());
  for (std::size_t k = 0; k < series.size(); ++k) {
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(k) / p.samples_per_cycle;
    time[k] = phase / (2.0 * std::numbers::pi) * p.period();
    rate[k] = std::cos(phase);
  }
  g.write("time", time, {},
          {"1/(gamma0 omega)",
           "time of each sample, in units of the inverse peak rate "
           "(cycle = 2 pi gamma0); phase = time/gamma0"});
  g.write("rate", rate, {}, {"gamma0 omega", "shear rate at each sample, cos(phase)"});
  write_time_series(std::move(g), series);
}

void write_cycles(H5Group& g, const std::vector<std::vector<double>>& cycles) {
  const std::vector<std::string>& names = oscillation_observable_names();
  std::vector<double> flat;
  for (const auto& c : cycles) flat.insert(flat.end(), c.begin(), c.end());
  std::string columns, units;
  for (const auto& name : names) {
    if (!columns.empty()) {
      columns += ',';
      units += ',';
    }
    columns += name;
    units += oscillation_table::unit_of(name);
  }
  g.write("cycles", flat, {cycles.size(), names.size()},
          {units, "each complete cycle's response, [cycle][column]; columns: " + columns});
}

void write_summary(H5Group&& g, const OscillationResult& r) {
  const PeriodicSummary& s = r.summary;
  g.set_attribute("converged", static_cast<std::int64_t>(r.converged));
  g.set_attribute("stop_reason", r.stop_reason);
  g.set_attribute("cycles", static_cast<std::int64_t>(s.cycles));
  g.set_attribute("transient_cycles", static_cast<std::int64_t>(s.transient_cycles));
  g.set_attribute("periodic", static_cast<std::int64_t>(s.periodic));
  g.set_attribute("drift", s.drift);
  g.set_attribute("drift_change", s.drift_change);
  for (const auto& o : s.observables) {
    H5Group q = g.create_group(o.name);
    q.set_attribute("mean", o.estimate.mean);
    q.set_attribute("standard_error", o.estimate.standard_error);
    q.set_attribute("samples", static_cast<std::int64_t>(o.estimate.samples));
    q.set_attribute("units", oscillation_table::unit_of(o.name));
  }
}

// The last complete cycle as a closed loop: σ against γ (elastic Lissajous)
// and against γ̇ (viscous), with the stress's parts.
void write_lissajous(H5Group&& g, const TimeSeries& series, const OscillationProtocol& p,
                     std::size_t cycles) {
  if (cycles == 0) return;
  const std::size_t n = p.samples_per_cycle, first = (cycles - 1) * n;
  const std::vector<double> sigma = series.component("sigma"),
                            elastic = series.component("sigma_elastic"),
                            viscous = series.component("sigma_viscous");
  std::vector<double> strain, rate, s, e, v;
  for (std::size_t k = 0; k <= n; ++k) {
    const std::size_t at = first + k;
    strain.push_back(series.strain[at] - series.strain[first]);
    rate.push_back(
        std::cos(2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n)));
    s.push_back(sigma[at]);
    e.push_back(elastic[at]);
    v.push_back(viscous[at]);
  }
  g.set_attribute("cycle", static_cast<std::int64_t>(cycles - 1));
  g.write("strain", strain, {}, {"1", "strain gamma0 sin(phase), the loop closed"});
  g.write("rate", rate, {}, {"gamma0 omega", "shear rate, cos(phase)"});
  g.write("sigma", s, {}, {"E*", "shear stress sigma_yx"});
  g.write("sigma_elastic", e, {}, {"E*", "its elastic part"});
  g.write("sigma_viscous", v, {}, {"E*", "its viscous part"});
}


}  // namespace

void write_oscillation(H5Group&& g, const OscillationRecord& record) {
  const OscillationResult& r = record.result;
  write_protocol(g, record.protocol);
  g.set_attribute("integrator", record.integrator);
  write_series(g.create_group("timeseries"), r.series, record.protocol);
  write_cycles(g, r.cycles);
  write_summary(g.create_group("summary"), r);
  write_lissajous(g.create_group("lissajous"), r.series, record.protocol, r.cycles.size());
  H5Group counters = g.create_group("counters");
  write_counters(counters, r.counters);
  write_configuration(g.create_group("configuration"), record.final_particles, record.final_box);
}

StoredOscillationSummary read_oscillation_summary(const std::filesystem::path& path) {
  const std::string expected = "an oscillatory run (micro oscillate's runs/*.h5)";
  const H5File file = open_micro_file(path, expected);
  const H5Group root = file.root();
  require_file_kind(root, path, {FileKind::oscillation_run}, expected);
  const std::string where = path.string();
  const H5Group packing = root.group("packing"), g = root.group("oscillation"),
                summary = g.group("summary");
  const auto positive = [&](const H5Group& group, const char* name) {
    const double v = group.read_scalar(name);
    if (!(v > 0 && std::isfinite(v)))
      throw InputError(fmt::format("'{}': dataset '{}/{}' = {}; allowed: finite and > 0", where,
                                   group.path(), name, v));
    return v;
  };
  const auto attribute = [&](const H5Group& group, const char* name) {
    return finite(group.attribute_double(name), where,
                  fmt::format("attribute '{}' of '{}'", name, group.path()));
  };
  StoredOscillationSummary s;
  s.file = path;
  s.packing_fingerprint = configuration_fingerprint(packing.group("configuration"));
  s.volume_fraction = positive(packing, "volume_fraction");
  s.shear_modulus = positive(packing, "shear_modulus");
  s.flow_gradient_modulus = positive(packing, "shear_modulus_flow_gradient");
  s.particles = count(packing.read_scalar("particles"), where, "dataset '/packing/particles'");
  s.amplitude = positive(g, "amplitude");
  s.frequency = positive(g, "frequency");
  s.converged = summary.attribute_int("converged") != 0;
  const auto cycles = [&](const char* name) {
    return count(static_cast<double>(summary.attribute_int(name)), where,
                 fmt::format("attribute '{}' of '{}'", name, summary.path()));
  };
  const std::size_t all = cycles("cycles"), transient = cycles("transient_cycles");
  if (transient > all)
    throw InputError(fmt::format("'{}': {} transient cycles of {}; allowed: at most all", where,
                                 transient, all));
  s.periodic_cycles = all - transient;
  for (const auto& name : oscillation_observable_names()) {
    const H5Group q = summary.group(name);
    MeanEstimate e;
    e.mean = attribute(q, "mean");
    e.standard_error = attribute(q, "standard_error");
    if (e.standard_error < 0)
      throw InputError(fmt::format("'{}': attribute 'standard_error' of '{}' = {}; allowed: >= 0",
                                   where, q.path(), e.standard_error));
    e.samples = count(static_cast<double>(q.attribute_int("samples")), where,
                      "attribute 'samples' of '" + q.path() + "'");
    s.observables.push_back({name, e});
  }
  return s;
}

}  // namespace softglass::micro
