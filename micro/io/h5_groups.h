// The HDF5 groups that run files and checkpoints share: a configuration, a
// sampled stress history, stored snapshots. Readers check shapes and name the
// file (`where`) and dataset in their errors.
#pragma once

#include <string>
#include <vector>

#include "common/h5_file.h"
#include "micro/protocol/shear_run.h"
#include "micro/system/lees_edwards_box.h"
#include "micro/system/particles.h"

namespace softglass::micro {

std::vector<double> flatten(const std::vector<Vec3>& v);
std::vector<Vec3> unflatten(const std::vector<double>& flat);

/// Positions, radii, velocities of `p` (in its order) and the cell.
void write_configuration(H5Group&& g, const Particles& p, const LeesEdwardsBox& box);

void write_time_series(H5Group&& g, const TimeSeries& t);
TimeSeries read_time_series(const H5Group& g, const std::string& where);

void write_snapshots(H5Group&& g, const std::vector<Snapshot>& snapshots);
/// Snapshots of `particles` particles each.
std::vector<Snapshot> read_snapshots(const H5Group& g, std::size_t particles, const std::string& where);

}  // namespace softglass::micro
