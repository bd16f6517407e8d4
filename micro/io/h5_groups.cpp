#include "micro/io/h5_groups.h"

#include <fmt/format.h>

#include "common/errors.h"

namespace softglass::micro {

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> flat;
  flat.reserve(3 * v.size());
  for (const Vec3& x : v) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
  return flat;
}

std::vector<Vec3> unflatten(const std::vector<double>& flat) {
  std::vector<Vec3> v(flat.size() / 3);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return v;
}

namespace {

std::vector<double> flatten(const std::vector<Eigen::Matrix3d>& m) {
  std::vector<double> flat;
  flat.reserve(9 * m.size());
  for (const auto& s : m)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) flat.push_back(s(i, j));  // row-major: [k][i][j] = σ_ij
  return flat;
}

}  // namespace

void write_configuration(H5Group&& g, const Particles& p, const LeesEdwardsBox& box) {
  g.write("position", flatten(p.position), {p.size(), 3},
          {"R", "particle centres in the primary cell [0, L)^3; x flow, y gradient, z vorticity"});
  g.write("radius", p.radius, {}, {"R", "particle radii (mean 1)"});
  g.write("velocity", flatten(p.velocity), {p.size(), 3},
          {"gamma_dot R", "non-affine velocity u - gamma_dot y e_x (zero for a packing)"});
  g.write_scalar("side", box.side(), {"R", "side L of the cubic cell"});
  g.write_scalar("strain", box.strain(), {"1", "accumulated Lees-Edwards strain"});
}

void write_time_series(H5Group&& ts, const TimeSeries& t) {
  ts.write("strain", t.strain, {}, {"1", "strain at each sample"});
  ts.write("stress_elastic", flatten(t.elastic), {t.size(), 3, 3},
           {"E*", "elastic stress tensor sigma^e_ij = -(1/V) sum d_i f_j, [sample][i][j]"});
  ts.write("stress_viscous", flatten(t.viscous), {t.size(), 3, 3},
           {"E*", "viscous (EHD) stress tensor sigma^v_ij, not symmetric, [sample][i][j]"});
  ts.write("coordination", t.coordination, {}, {"1", "Z = 2 x contacts / N"});
  ts.write(
      "layering", t.layering, {},
      {"1", "S_y = max_m |sum exp(2 pi i m y/L)|^2 / N; about 3 when disordered, > 20 layered"});
  ts.write("step", t.step, {}, {"1", "last accepted integrator step (strain)"});
}

TimeSeries read_time_series(const H5Group& ts, const std::string& where) {
  TimeSeries t;
  t.strain = ts.read_array("strain").data;
  t.coordination = ts.read_array("coordination").data;
  t.layering = ts.read_array("layering").data;
  t.step = ts.read_array("step").data;
  const auto tensors = [&](const char* name) {
    const H5Array a = ts.read_array(name);
    if (a.dims.size() != 3 || a.dims[0] != t.strain.size() || a.dims[1] != 3 || a.dims[2] != 3) {
      throw InputError(fmt::format("'{}': dataset '{}' must have shape n x 3 x 3", where, name));
    }
    std::vector<Eigen::Matrix3d> m(a.dims[0]);
    for (std::size_t k = 0; k < m.size(); ++k)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[k](i, j) = a.data[9 * k + 3 * i + j];
    return m;
  };
  t.elastic = tensors("stress_elastic");
  t.viscous = tensors("stress_viscous");
  if (t.coordination.size() != t.size() || t.step.size() != t.size() || t.layering.size() != t.size()) {
    throw InputError(fmt::format("'{}': time-series datasets differ in length", where));
  }
  return t;
}

void write_snapshots(H5Group&& g, const std::vector<Snapshot>& snapshots) {
  std::vector<double> strain, position;
  for (const Snapshot& snap : snapshots) {
    strain.push_back(snap.strain);
    for (const Vec3& x : snap.position) position.insert(position.end(), {x.x(), x.y(), x.z()});
  }
  const std::size_t n = snapshots.empty() ? 0 : snapshots.front().position.size();
  g.write("strain", strain, {}, {"1", "strain of each stored configuration"});
  g.write("position", position, {strain.size(), 3 * n},
          {"R", "configurations [snapshot][3 i + axis], label order, in the cell"});
}

std::vector<Snapshot> read_snapshots(const H5Group& g, std::size_t n, const std::string& where) {
  const std::vector<double> strain = g.read_array("strain").data;
  const H5Array position = g.read_array("position");
  if (position.dims.size() != 2 || position.dims[0] != strain.size() || position.dims[1] != 3 * n) {
    throw InputError(fmt::format("'{}': snapshot positions must have shape {} x {}", where,
                                 strain.size(), 3 * n));
  }
  std::vector<Snapshot> snapshots;
  for (std::size_t k = 0; k < strain.size(); ++k) {
    Snapshot snap{strain[k], std::vector<Vec3>(n)};
    const double* p = &position.data[k * 3 * n];
    for (std::size_t i = 0; i < n; ++i) snap.position[i] = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    snapshots.push_back(std::move(snap));
  }
  return snapshots;
}

}  // namespace softglass::micro
