#include "micro/io/checkpoint_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"
#include "micro/io/h5_groups.h"

namespace softglass::micro {

namespace {

constexpr const char* kShearKind = "softglass shear checkpoint";
constexpr const char* kQuasiStaticKind = "softglass quasi-static checkpoint";

// The minimiser's counters, in declaration order, appended to `values`.
void append_minimiser(const IncrementalCounters& m, std::vector<double>& values) {
  values.insert(values.end(), {double(m.solves), double(m.iterations), double(m.cg_iterations),
                               double(m.force_evaluations), double(m.assemblies),
                               double(m.damping_raises), double(m.backtracks)});
}
constexpr std::size_t kMinimiserCounters = 7;
constexpr const char* kMinimiserCounterNames =
    "minimiser solves, Newton iterations, CG iterations, force evaluations, assemblies, damping "
    "raises, backtracks";

// The counters as one array, in this order. The rejections by cause, the drag
// freezes and the minimiser's counters were appended later: an older
// checkpoint holds only the first 9, and a run resumed from it counts those
// from the resumption on.
constexpr std::size_t kOlderShearCounters = 9;
constexpr std::size_t kShearCounters = kOlderShearCounters + 4 + kMinimiserCounters;
std::vector<double> counter_values(const ShearCounters& c) {
  std::vector<double> values{double(c.steps),
                             double(c.rejected_steps),
                             double(c.evaluations),
                             double(c.neighbour_builds),
                             double(c.fixed_point_sweeps),
                             double(c.newton_iterations),
                             double(c.cg_iterations),
                             c.smallest_step,
                             c.largest_step,
                             double(c.rejected_error),
                             double(c.rejected_list),
                             double(c.rejected_solver),
                             double(c.drag_freezes)};
  append_minimiser(c.minimiser, values);
  return values;
}

// What every checkpoint holds: its kind, its run's parameter text (none in
// some tests), the configuration, the run's state and counters as two arrays,
// the series and the snapshots so far.
struct Parts {
  const char* kind;
  const std::string& parameters;
  const Particles& particles;
  const LeesEdwardsBox& box;
  std::vector<double> state;
  const char* state_names;
  std::vector<double> counters;
  const char* counter_names;
  const TimeSeries& series;
  const std::vector<Snapshot>& snapshots;
};

// Writes `parts` (and what `more` adds) atomically to `path`.
void write_parts(const std::filesystem::path& path, const Parts& parts,
                 const std::function<void(H5Group&)>& more = {}) {
  AtomicOutput out(path, true);
  {
    H5File file = H5File::create(out.temporary_path());
    H5Group root = file.root();
    root.set_attribute("kind", std::string(parts.kind));
    if (!parts.parameters.empty())
      root.write_string("parameters", parts.parameters,
                        {"", "the parameter text of the run's record (micro/io/run_file.h)"});
    write_configuration(root.create_group("configuration"), parts.particles, parts.box);
    if (more) more(root);
    root.write("state", parts.state, {}, {"", parts.state_names});
    root.write("counters", parts.counters, {}, {"", parts.counter_names});
    if (parts.series.size() > 0) write_time_series(root.create_group("timeseries"), parts.series);
    if (!parts.snapshots.empty()) write_snapshots(root.create_group("snapshots"), parts.snapshots);
    file.close();
  }
  out.commit();
}

struct ReadParts {
  std::string where;
  StoredConfiguration configuration;
  std::vector<double> state, counters;
  TimeSeries series;
  std::vector<Snapshot> snapshots;

  // Entries of /state and /counters, checked: finite, a count, or the worst
  // error (inf until the first check; NaN or negative, never).
  double finite_state(std::size_t k) const {
    return finite(state[k], where, fmt::format("value {} of dataset '/state'", k));
  }
  double worst_error(std::size_t k) const {
    if (!(state[k] >= 0))
      throw InputError(
          fmt::format("'{}': worst error = {} in '/state'; allowed: >= 0", where, state[k]));
    return state[k];
  }
  std::size_t count_at(std::size_t k) const {
    return count(counters[k], where, fmt::format("value {} of dataset '/counters'", k));
  }
  double finite_counter(std::size_t k) const {
    return finite(counters[k], where, fmt::format("value {} of dataset '/counters'", k));
  }
  // The minimiser's counters from entry `first` on (append_minimiser), or
  // none in a checkpoint from before they were stored.
  IncrementalCounters minimiser_at(std::size_t first) const {
    if (counters.size() < first + kMinimiserCounters) return {};
    return {count_at(first),     count_at(first + 1), count_at(first + 2), count_at(first + 3),
            count_at(first + 4), count_at(first + 5), count_at(first + 6)};
  }
};

// The parts of a checkpoint of `kind` with state and counters of the given
// lengths (the state's at least `state_size`, at most `longest_state`; the
// counters' `counters_size`, or `older_counters` in a checkpoint written
// before the last counters were added).
ReadParts read_parts(const H5Group& root, const std::string& where, const char* kind,
                     std::size_t state_size, std::size_t counters_size, std::size_t older_counters,
                     std::size_t longest_state = 0) {
  if (!root.has_attribute("kind") || root.attribute_string("kind") != kind) {
    const bool other =
        root.has_attribute("kind") && (root.attribute_string("kind") == kShearKind ||
                                       root.attribute_string("kind") == kQuasiStaticKind);
    throw InputError(
        other ? fmt::format("'{}' is a {}, not a {}", where, root.attribute_string("kind"), kind)
              : fmt::format("'{}' is not a softglass checkpoint", where));
  }
  ReadParts p{where,
              read_configuration(root.group("configuration"), where),
              root.read_array("state").data,
              root.read_array("counters").data,
              {},
              {}};
  const std::size_t longest = std::max(state_size, longest_state);
  if (p.state.size() < state_size || p.state.size() > longest ||
      (p.counters.size() != counters_size && p.counters.size() != older_counters))
    throw InputError(fmt::format("'{}': state or counters of the wrong length", where));
  if (root.has_child("timeseries")) p.series = read_time_series(root.group("timeseries"), where);
  if (root.has_child("snapshots"))
    p.snapshots = read_snapshots(root.group("snapshots"), p.configuration.particles.size(), where);
  return p;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& c,
                      const std::string& parameters) {
  write_parts(path,
              {kShearKind,
               parameters,
               c.particles,
               c.box,
               {c.start, c.next_sample, c.next_check, c.next_snapshot, c.worst, c.seconds,
                c.amplitude, c.time.value_or(0.0)},
               "start, next sample, next check, next snapshot, worst error, seconds, drive "
               "amplitude, time",
               counter_values(c.counters),
               "ShearCounters in declaration order (the minimiser's in theirs)",
               c.series,
               c.snapshots},
              [&](H5Group& root) {
                root.write("label", std::span<const std::uint32_t>(c.particles.label), {},
                           {"1", "label of each particle, engine order"});
              });
}

ShearCheckpoint read_checkpoint(const std::filesystem::path& path) {
  const std::string where = path.string();
  const H5File file = H5File::open(path);
  const H5Group root = file.root();
  // The drive's amplitude and the time were added after the first six
  // entries: a checkpoint of six is of steady shear.
  ReadParts parts = read_parts(root, where, kShearKind, 6, kShearCounters, kOlderShearCounters, 8);
  if (parts.state.size() == 7)
    throw InputError(fmt::format("'{}': 7 state entries; allowed: 6 or 8", where));
  ShearCheckpoint c;
  c.particles = std::move(parts.configuration.particles);
  c.box = parts.configuration.box;
  // The labels index the particles: a permutation of 0 ... N-1.
  const std::vector<std::int64_t> labels = root.read_int_array("label");
  const std::size_t n = c.particles.size();
  if (labels.size() != n) {
    throw InputError(fmt::format("'{}': {} labels for {} particles; allowed: one per particle",
                                 where, labels.size(), n));
  }
  std::vector<bool> seen(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t label = labels[i];
    if (label < 0 || static_cast<std::size_t>(label) >= n ||
        seen[static_cast<std::size_t>(label)]) {
      throw InputError(fmt::format("'{}': label {} of particle {}; allowed: each of 0 ... {} once",
                                   where, label, i, n - 1));
    }
    seen[static_cast<std::size_t>(label)] = true;
    c.particles.label[i] = static_cast<std::uint32_t>(label);
  }
  c.start = parts.finite_state(0);
  c.next_sample = parts.finite_state(1);
  c.next_check = parts.finite_state(2);
  c.next_snapshot = parts.finite_state(3);
  c.worst = parts.worst_error(4);
  c.seconds = parts.finite_state(5);
  if (parts.state.size() == 8) {
    c.amplitude = parts.finite_state(6);
    c.time = parts.finite_state(7);
  }
  const bool older = parts.counters.size() == kOlderShearCounters;
  c.counters = {.steps = parts.count_at(0),
                .rejected_steps = parts.count_at(1),
                .evaluations = parts.count_at(2),
                .neighbour_builds = parts.count_at(3),
                .fixed_point_sweeps = parts.count_at(4),
                .newton_iterations = parts.count_at(5),
                .cg_iterations = parts.count_at(6),
                .smallest_step = parts.finite_counter(7),
                .largest_step = parts.finite_counter(8),
                .rejected_error = older ? 0 : parts.count_at(9),
                .rejected_list = older ? 0 : parts.count_at(10),
                .rejected_solver = older ? 0 : parts.count_at(11),
                .drag_freezes = older ? 0 : parts.count_at(12),
                .minimiser = parts.minimiser_at(13)};
  c.series = std::move(parts.series);
  c.snapshots = std::move(parts.snapshots);
  return c;
}

// A quasi-static checkpoint's counters: 5, then (appended later) the minimiser's.
constexpr std::size_t kOlderQuasiStaticCounters = 5;

void write_checkpoint(const std::filesystem::path& path, const QuasiStaticCheckpoint& c,
                      const std::string& parameters) {
  std::vector<double> counters{double(c.counters.steps), double(c.counters.newton_iterations),
                               double(c.counters.cg_iterations), double(c.stress_drops),
                               double(c.unconverged_steps)};
  append_minimiser(c.counters.minimiser, counters);
  const std::string names =
      fmt::format("steps, Newton iterations, CG iterations, stress drops, unconverged steps, {}",
                  kMinimiserCounterNames);
  write_parts(path, {kQuasiStaticKind,
                     parameters,
                     c.particles,
                     c.box,
                     {c.start, c.next_check, c.worst, c.last_sigma, c.seconds},
                     "start, next check, worst error, last sigma, seconds",
                     counters,
                     names.c_str(),
                     c.series,
                     c.snapshots});
}

QuasiStaticCheckpoint read_quasi_static_checkpoint(const std::filesystem::path& path) {
  const std::string where = path.string();
  const H5File file = H5File::open(path);
  ReadParts parts =
      read_parts(file.root(), where, kQuasiStaticKind, 5,
                 kOlderQuasiStaticCounters + kMinimiserCounters, kOlderQuasiStaticCounters);
  QuasiStaticCheckpoint c;
  c.particles = std::move(parts.configuration.particles);  // label order: labels 0 ... N-1
  c.box = parts.configuration.box;
  c.start = parts.finite_state(0);
  c.next_check = parts.finite_state(1);
  c.worst = parts.worst_error(2);
  c.last_sigma = parts.finite_state(3);
  c.seconds = parts.finite_state(4);
  c.counters.steps = parts.count_at(0);
  c.counters.newton_iterations = parts.count_at(1);
  c.counters.cg_iterations = parts.count_at(2);
  c.stress_drops = parts.count_at(3);
  c.unconverged_steps = parts.count_at(4);
  c.counters.minimiser = parts.minimiser_at(kOlderQuasiStaticCounters);
  c.series = std::move(parts.series);
  c.snapshots = std::move(parts.snapshots);
  return c;
}

}  // namespace softglass::micro
