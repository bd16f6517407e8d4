#include "micro/io/checkpoint_file.h"

#include <fmt/format.h>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"
#include "micro/io/h5_groups.h"

namespace softglass::micro {

namespace {

// The counters as one array, in this order.
std::vector<double> counter_values(const ShearCounters& c) {
  return {double(c.steps),          double(c.rejected_steps),    double(c.evaluations),
          double(c.neighbour_builds), double(c.fixed_point_sweeps), double(c.newton_iterations),
          double(c.cg_iterations),  c.smallest_step,             c.largest_step};
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const ShearCheckpoint& c) {
  AtomicOutput out(path, true);
  {
    H5File file = H5File::create(out.temporary_path());
    H5Group root = file.root();
    root.set_attribute("kind", std::string("softglass shear checkpoint"));
    write_configuration(root.create_group("configuration"), c.particles, c.box);
    root.write("label", std::span<const std::uint32_t>(c.particles.label), {},
               {"1", "label of each particle, engine order"});
    root.write("state", std::vector<double>{c.start, c.next_sample, c.next_check, c.next_snapshot, c.worst, c.seconds},
               {}, {"", "start, next sample, next check, next snapshot, worst error, seconds"});
    root.write("counters", counter_values(c.counters), {}, {"", "ShearCounters in declaration order"});
    if (c.series.size() > 0) write_time_series(root.create_group("timeseries"), c.series);
    if (!c.snapshots.empty()) write_snapshots(root.create_group("snapshots"), c.snapshots);
    file.close();
  }
  out.commit();
}

ShearCheckpoint read_checkpoint(const std::filesystem::path& path) {
  const std::string where = path.string();
  const H5File file = H5File::open(path);
  const H5Group root = file.root();
  if (!root.has_attribute("kind") || root.attribute_string("kind") != "softglass shear checkpoint")
    throw InputError(fmt::format("'{}' is not a softglass checkpoint", where));
  ShearCheckpoint c;
  StoredConfiguration configuration = read_configuration(root.group("configuration"), where);
  c.particles = std::move(configuration.particles);
  c.box = configuration.box;
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
  const std::vector<double> state = root.read_array("state").data;
  const std::vector<double> counters = root.read_array("counters").data;
  if (state.size() != 6 || counters.size() != 9)
    throw InputError(fmt::format("'{}': state or counters of the wrong length", where));
  const auto finite_state = [&](std::size_t k) {
    return finite(state[k], where, fmt::format("value {} of dataset '/state'", k));
  };
  c.start = finite_state(0);
  c.next_sample = finite_state(1);
  c.next_check = finite_state(2);
  c.next_snapshot = finite_state(3);
  // The worst error is inf until the first check; NaN or negative, never.
  c.worst = state[4];
  if (!(c.worst >= 0))
    throw InputError(
        fmt::format("'{}': worst error = {} in '/state'; allowed: >= 0", where, c.worst));
  c.seconds = finite_state(5);
  const auto counter = [&](std::size_t k) {
    return count(counters[k], where, fmt::format("value {} of dataset '/counters'", k));
  };
  const auto step = [&](std::size_t k) {
    return finite(counters[k], where, fmt::format("value {} of dataset '/counters'", k));
  };
  c.counters = {counter(0), counter(1), counter(2), counter(3), counter(4),
                counter(5), counter(6), step(7),    step(8)};
  if (root.has_child("timeseries")) c.series = read_time_series(root.group("timeseries"), where);
  if (root.has_child("snapshots"))
    c.snapshots = read_snapshots(root.group("snapshots"), c.particles.size(), where);
  return c;
}

}  // namespace softglass::micro
