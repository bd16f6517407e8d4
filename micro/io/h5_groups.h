// The HDF5 groups that run files and checkpoints share: a configuration, a
// sampled stress history, stored snapshots. Readers check shapes and name the
// file (`where`) and dataset in their errors.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/h5_file.h"
#include "micro/geometry/lees_edwards_box.h"
#include "micro/geometry/particles.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

std::vector<double> flatten(const std::vector<Vec3>& v);
std::vector<Vec3> unflatten(const std::vector<double>& flat);

// Readers take nothing on trust: a file may be damaged, or written by another
// program. What they return is computed with, so NaN, inf or a negative count
// in it is refused here, with InputError naming the file (`where`), the
// dataset or attribute (`name`), the value and what is allowed.

/// `value`, if finite.
double finite(double value, const std::string& where, const std::string& name);
/// `value` as a count, if a whole number in 0 … 2^53.
std::size_t count(double value, const std::string& where, const std::string& name);
/// Every value of the dataset `name` of `g`, if each is finite.
std::vector<double> read_finite(const H5Group& g, const std::string& name,
                                const std::string& where);

/// Positions, radii, velocities of `p` (in its order) and the cell.
void write_configuration(H5Group&& g, const Particles& p, const LeesEdwardsBox& box);
/// What write_configuration wrote, checked: positions and velocities N x 3 and
/// finite, N radii finite and > 0, the side finite and > 0, the strain finite.
struct StoredConfiguration {
  Particles particles;
  LeesEdwardsBox box;
};
StoredConfiguration read_configuration(const H5Group& g, const std::string& where);

/// A hash of a stored configuration (FNV-1a over its positions and radii):
/// equal for two runs of one packing, a run and its copy included.
std::uint64_t configuration_fingerprint(const H5Group& configuration);

void write_time_series(H5Group&& g, const TimeSeries& t);
TimeSeries read_time_series(const H5Group& g, const std::string& where);

void write_snapshots(H5Group&& g, const std::vector<Snapshot>& snapshots);

/// A run's counters as attributes of `g` (steps, rejections and their causes,
/// evaluations, list builds, solver iterations, smallest and largest step, the
/// minimisations' work; docs/output.md).
void write_counters(H5Group& g, const ShearCounters& counters);
/// Snapshots of `particles` particles each.
std::vector<Snapshot> read_snapshots(const H5Group& g, std::size_t particles,
                                     const std::string& where);

}  // namespace softglass::micro
