#include "micro/io/h5_groups.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <utility>

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
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
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

// "/shear/timeseries/strain": the path of the child `name` of `g`, for messages.
std::string child_path(const H5Group& g, const std::string& name) {
  const std::string base = g.path();
  return (base == "/" ? "" : base) + "/" + name;
}

// An N x 3 dataset of finite numbers as N vectors.
std::vector<Vec3> read_vectors(const H5Group& g, const std::string& name,
                               const std::string& where) {
  const std::vector<std::size_t> dims = g.dims(name);
  if (dims.size() != 2 || dims[1] != 3) {
    throw InputError(fmt::format("'{}': dataset '{}' has shape {}; allowed: N x 3", where,
                                 child_path(g, name), fmt::join(dims, " x ")));
  }
  return unflatten(read_finite(g, name, where));
}

}  // namespace

// FNV-1a over the bytes of a configuration's positions and radii.
std::uint64_t configuration_fingerprint(const H5Group& configuration) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const char* name : {"position", "radius"}) {
    for (const double x : configuration.read_array(name).data) {
      const auto* byte = reinterpret_cast<const unsigned char*>(&x);
      for (std::size_t k = 0; k < sizeof x; ++k) hash = (hash ^ byte[k]) * 1099511628211ull;
    }
  }
  return hash;
}

void write_counters(H5Group& c, const ShearCounters& k) {
  const IncrementalCounters& m = k.minimiser;
  const std::pair<const char*, std::size_t> counts[] = {
      {"steps", k.steps},
      {"rejected_steps", k.rejected_steps},
      {"evaluations", k.evaluations},
      {"neighbour_builds", k.neighbour_builds},
      {"fixed_point_sweeps", k.fixed_point_sweeps},
      {"newton_iterations", k.newton_iterations},
      {"cg_iterations", k.cg_iterations},
      {"rejected_error", k.rejected_error},
      {"rejected_list", k.rejected_list},
      {"rejected_solver", k.rejected_solver},
      {"drag_freezes", k.drag_freezes},
      {"minimiser_solves", m.solves},
      {"minimiser_newton_iterations", m.iterations},
      {"minimiser_cg_iterations", m.cg_iterations},
      {"minimiser_force_evaluations", m.force_evaluations},
      {"minimiser_assemblies", m.assemblies},
      {"minimiser_damping_raises", m.damping_raises},
      {"minimiser_backtracks", m.backtracks}};
  for (const auto& [name, value] : counts) c.set_attribute(name, static_cast<std::int64_t>(value));
  c.set_attribute("smallest_step", k.smallest_step);
  c.set_attribute("largest_step", k.largest_step);
}

void write_configuration(H5Group&& g, const Particles& p, const LeesEdwardsBox& box) {
  g.write("position", flatten(p.position), {p.size(), 3},
          {"R", "particle centres in the primary cell [0, L)^3; x flow, y gradient, z vorticity"});
  g.write("radius", p.radius, {}, {"R", "particle radii (mean 1)"});
  g.write("velocity", flatten(p.velocity), {p.size(), 3},
          {"gamma_dot R", "non-affine velocity u - gamma_dot y e_x (zero for a packing)"});
  g.write_scalar("side", box.side(), {"R", "side L of the cubic cell"});
  g.write_scalar("strain", box.strain(), {"1", "accumulated Lees-Edwards strain"});
}

double finite(double value, const std::string& where, const std::string& name) {
  if (!std::isfinite(value))
    throw InputError(fmt::format("'{}': {} holds {}; allowed: finite numbers", where, name, value));
  return value;
}

std::size_t count(double value, const std::string& where, const std::string& name) {
  constexpr double kLargest = 9007199254740992.0;  // 2^53: doubles hold every count up to it
  if (!(value >= 0 && value <= kLargest && value == std::floor(value))) {
    throw InputError(
        fmt::format("'{}': {} = {}; allowed: a whole number in 0 ... 2^53", where, name, value));
  }
  return static_cast<std::size_t>(value);
}

std::vector<double> read_finite(const H5Group& g, const std::string& name,
                                const std::string& where) {
  std::vector<double> values = g.read_array(name).data;
  const std::string label = fmt::format("dataset '{}'", child_path(g, name));
  for (const double v : values) finite(v, where, label);
  return values;
}

StoredConfiguration read_configuration(const H5Group& g, const std::string& where) {
  std::vector<Vec3> position = read_vectors(g, "position", where);
  std::vector<double> radius = read_finite(g, "radius", where);
  std::vector<Vec3> velocity = read_vectors(g, "velocity", where);
  if (radius.size() != position.size() || velocity.size() != position.size()) {
    throw InputError(
        fmt::format("'{}': {} positions, {} radii and {} velocities in '{}'; allowed: "
                    "as many of each",
                    where, position.size(), radius.size(), velocity.size(), g.path()));
  }
  for (const double r : radius) {
    if (!(r > 0))
      throw InputError(fmt::format("'{}': a radius in '{}' is {}; allowed: > 0", where,
                                   child_path(g, "radius"), r));
  }
  const double side = g.read_scalar("side");
  if (!(side > 0 && std::isfinite(side))) {
    throw InputError(
        fmt::format("'{}': {} = {}; allowed: finite and > 0", where, child_path(g, "side"), side));
  }
  // LeesEdwardsBox keeps the whole strain as a 64-bit integer; no run comes near 1e12.
  const double strain = g.read_scalar("strain");
  if (!(std::abs(strain) <= 1e12)) {
    throw InputError(fmt::format("'{}': {} = {}; allowed: |strain| <= 1e12", where,
                                 child_path(g, "strain"), strain));
  }
  StoredConfiguration c{Particles(std::move(position), std::move(radius)), LeesEdwardsBox(side)};
  c.particles.velocity = std::move(velocity);
  c.box.set_strain(strain);
  return c;
}

void write_time_series(H5Group&& ts, const TimeSeries& t) {
  ts.write("strain", t.strain, {}, {"1", "strain at each sample"});
  ts.write("stress_elastic", flatten(t.elastic), {t.size(), 3, 3},
           {"E*", "elastic stress tensor sigma^e_ij = -(1/V) sum d_i f_j, [sample][i][j]"});
  ts.write("stress_viscous", flatten(t.viscous), {t.size(), 3, 3},
           {"E*",
            "viscous stress tensor sigma^v_ij (EHD films and Stokes pair dashpots), "
            "not symmetric, [sample][i][j]"});
  ts.write("stress_film", flatten(t.film), {t.size(), 3, 3},
           {"E*", "the EHD films' part of sigma^v_ij, [sample][i][j]"});
  ts.write("coordination", t.coordination, {}, {"1", "Z = 2 x contacts / N"});
  ts.write(
      "layering", t.layering, {},
      {"1", "S_y = max_m |sum exp(2 pi i m y/L)|^2 / N; about 3 when disordered, > 20 layered"});
  ts.write("step", t.step, {}, {"1", "last accepted integrator step (strain)"});
}

TimeSeries read_time_series(const H5Group& ts, const std::string& where) {
  TimeSeries t;
  t.strain = read_finite(ts, "strain", where);
  t.coordination = read_finite(ts, "coordination", where);
  t.layering = read_finite(ts, "layering", where);
  t.step = read_finite(ts, "step", where);
  const auto tensors = [&](const char* name) {
    const H5Array a{read_finite(ts, name, where), ts.dims(name)};
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
  if (!ts.has_child("stress_film")) {
    throw InputError(
        fmt::format("'{}': no dataset 'stress_film' (the films' part of the viscous "
                    "stress): written before softglass recorded it; run it again",
                    where));
  }
  t.film = tensors("stress_film");
  if (t.coordination.size() != t.size() || t.step.size() != t.size() ||
      t.layering.size() != t.size()) {
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
  const std::vector<double> strain = read_finite(g, "strain", where);
  const H5Array position{read_finite(g, "position", where), g.dims("position")};
  if (position.dims.size() != 2 || position.dims[0] != strain.size() || position.dims[1] != 3 * n) {
    throw InputError(fmt::format("'{}': snapshot positions must have shape {} x {}", where,
                                 strain.size(), 3 * n));
  }
  std::vector<Snapshot> snapshots;
  for (std::size_t k = 0; k < strain.size(); ++k) {
    Snapshot snap{strain[k], std::vector<Vec3>(n)};
    const double* p = &position.data[k * 3 * n];
    for (std::size_t i = 0; i < n; ++i)
      snap.position[i] = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    snapshots.push_back(std::move(snap));
  }
  return snapshots;
}

}  // namespace softglass::micro
