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

// The counters as one array, in this order.
std::vector<double> counter_values(const ShearCounters& c) {
  return {double(c.steps),
          double(c.rejected_steps),
          double(c.evaluations),
          double(c.neighbour_builds),
          double(c.fixed_point_sweeps),
          double(c.newton_iterations),
          double(c.cg_iterations),
          c.smallest_step,
          c.largest_step};
}

// What every checkpoint holds: its kind, the configuration, the run's state
// and counters as two arrays, the series and the snapshots so far.
struct Parts {
  const char* kind;
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
};

// The parts of a checkpoint of `kind` with state and counters of the given
// lengths (the state's at least `state_size`, at most `longest_state`).
ReadParts read_parts(const H5Group& root, const std::string& where, const char* kind,
                     std::size_t state_size, std::size_t counters_size,
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
  if (p.state.size() < state_size || p.state.size() > longest || p.counters.size() != counters_size)
    throw InputError(fmt::format("'{}': state or counters of the wrong length", where));
  if (root.has_child("timeseries")) p.series = read_time_series(root.group("timeseries"), where);
  if (root.has_child("snapshots"))
    p.snapshots = read_snapshots(root.group("snapshots"), p.configuration.particles.size(), where);
  return p;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& c) {
  write_parts(path,
              {kShearKind,
               c.particles,
               c.box,
               {c.start, c.next_sample, c.next_check, c.next_snapshot, c.worst, c.seconds,
                c.amplitude, c.time.value_or(0.0)},
               "start, next sample, next check, next snapshot, worst error, seconds, drive "
               "amplitude, time",
               counter_values(c.counters),
               "ShearCounters in declaration order",
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
  ReadParts parts = read_parts(root, where, kShearKind, 6, 9, 8);
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
  c.counters = {parts.count_at(0), parts.count_at(1),       parts.count_at(2),
                parts.count_at(3), parts.count_at(4),       parts.count_at(5),
                parts.count_at(6), parts.finite_counter(7), parts.finite_counter(8)};
  c.series = std::move(parts.series);
  c.snapshots = std::move(parts.snapshots);
  return c;
}

void write_checkpoint(const std::filesystem::path& path, const QuasiStaticCheckpoint& c) {
  write_parts(path, {kQuasiStaticKind,
                     c.particles,
                     c.box,
                     {c.start, c.next_check, c.worst, c.last_sigma, c.seconds},
                     "start, next check, worst error, last sigma, seconds",
                     {double(c.counters.steps), double(c.counters.newton_iterations),
                      double(c.counters.cg_iterations), double(c.stress_drops),
                      double(c.unconverged_steps)},
                     "steps, Newton iterations, CG iterations, stress drops, unconverged steps",
                     c.series,
                     c.snapshots});
}

QuasiStaticCheckpoint read_quasi_static_checkpoint(const std::filesystem::path& path) {
  const std::string where = path.string();
  const H5File file = H5File::open(path);
  ReadParts parts = read_parts(file.root(), where, kQuasiStaticKind, 5, 5);
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
  c.series = std::move(parts.series);
  c.snapshots = std::move(parts.snapshots);
  return c;
}

}  // namespace softglass::micro
