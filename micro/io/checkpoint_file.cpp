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
  const H5Group g = root.group("configuration");
  c.particles = Particles(unflatten(g.read_array("position").data), g.read_array("radius").data);
  c.particles.velocity = unflatten(g.read_array("velocity").data);
  c.particles.label.clear();
  for (double label : root.read_array("label").data) c.particles.label.push_back(static_cast<std::uint32_t>(label));
  if (c.particles.velocity.size() != c.particles.size() || c.particles.label.size() != c.particles.size())
    throw InputError(fmt::format("'{}': configuration arrays differ in length", where));
  c.box = LeesEdwardsBox(g.read_scalar("side"));
  c.box.set_strain(g.read_scalar("strain"));
  const std::vector<double> state = root.read_array("state").data;
  const std::vector<double> counters = root.read_array("counters").data;
  if (state.size() != 6 || counters.size() != 9)
    throw InputError(fmt::format("'{}': state or counters of the wrong length", where));
  c.start = state[0];
  c.next_sample = state[1];
  c.next_check = state[2];
  c.next_snapshot = state[3];
  c.worst = state[4];
  c.seconds = state[5];
  const auto count = [&](int k) { return static_cast<std::size_t>(counters[static_cast<std::size_t>(k)]); };
  c.counters = {count(0), count(1), count(2), count(3), count(4), count(5), count(6), counters[7], counters[8]};
  if (root.has_child("timeseries")) c.series = read_time_series(root.group("timeseries"), where);
  if (root.has_child("snapshots"))
    c.snapshots = read_snapshots(root.group("snapshots"), c.particles.size(), where);
  return c;
}

}  // namespace softglass::micro
