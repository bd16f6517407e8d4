#include "micro/io/run_file.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <fstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"
#include "common/version.h"
#include "micro/io/h5_groups.h"

namespace softglass::micro {

namespace {

// Format 2: /packing/shear_modulus is the mean over the six simple shears
// (format 1 held the x–y shear alone, a different number for the same packing).
constexpr std::int64_t kFormatVersion = 2;

// The attribute `protocol` of /shear; files written before it existed are overdamped.
constexpr const char* kOverdamped = "overdamped";
constexpr const char* kQuasiStatic = "aqs";

void write_packing(H5Group& g, const PackingReport& r, const ShearModulus& m) {
  const auto scalar = [&](const char* name, double value, const char* units, const char* what) {
    g.write_scalar(name, value, {units, what});
  };
  scalar("particles", static_cast<double>(r.particles), "1", "number of particles N");
  scalar("volume_fraction", r.volume_fraction, "1", "phi = sum (4/3) pi R^3 / V");
  scalar("side", r.side, "R", "cell side L");
  scalar("coordination", r.coordination, "1", "Z = 2 x contacts / N");
  scalar("coordination_nonrattler", r.coordination_nonrattler, "1",
         "Z of the backbone after removing rattlers (< 4 contacts, iteratively)");
  scalar("rattlers", static_cast<double>(r.rattlers), "1", "number of rattlers");
  scalar("mean_deformation", r.mean_deformation, "1", "mean contact deformation eps = h/R_c");
  scalar("max_deformation", r.max_deformation, "1", "largest contact deformation");
  scalar("pressure", r.pressure, "E*", "Pi = -tr(sigma^e)/3");
  scalar("energy_per_particle", r.energy_per_particle, "E* R^3", "elastic energy per particle");
  scalar("residual", r.residual, "1", "max |F_i| / mean contact force after relaxation");
  scalar("iterations", static_cast<double>(r.iterations), "1", "FIRE iterations, all stages");
  scalar("converged", r.converged ? 1.0 : 0.0, "1", "1 if the residual met the tolerance");
  scalar("shear_modulus", m.modulus, "E*",
         "G0, linear shear modulus (exact linear response), mean over the six simple shears");
  scalar("shear_modulus_flow_gradient", m.flow_gradient_modulus, "E*",
         "linear modulus of the x-y simple shear alone");
  scalar("shear_modulus_direction_sd", m.direction_spread, "E*",
         "standard deviation of the six simple-shear moduli");
  scalar("affine_shear_modulus", m.affine_modulus, "E*", "affine (unrelaxed) shear modulus");
  scalar("shear_modulus_solver_error", m.solver_error, "1", "relative residual of H u = Xi");
}

void write_shear(H5Group&& g, const ShearRecord& s) {
  const ShearResult& r = s.result;
  g.set_attribute("protocol", std::string(s.quasi_static ? kQuasiStatic : kOverdamped));
  g.write_scalar("gamma_tilde", s.gamma_tilde,
                 {"1", "dimensionless shear rate gamma_dot eta_s / E* (0: quasi-static)"});
  if (!s.integrator.empty()) g.set_attribute("integrator", s.integrator);
  if (s.quasi_static) {
    g.set_attribute("strain_step", s.quasi_static->strain_step);
    g.set_attribute("relative_force", s.quasi_static->relative_force);
  }

  write_time_series(g.create_group("timeseries"), r.series);

  H5Group sum = g.create_group("summary");
  sum.set_attribute("converged", static_cast<std::int64_t>(r.converged));
  sum.set_attribute("stop_reason", r.stop_reason);
  sum.set_attribute("transient_strain", r.summary.transient_strain);
  sum.set_attribute("averaged_strain", r.summary.averaged_strain);
  sum.set_attribute("transient_resolved", static_cast<std::int64_t>(r.summary.transient_resolved));
  sum.set_attribute("elastic_to_viscous", r.summary.elastic_to_viscous);
  sum.set_attribute("elastic_to_film", r.summary.elastic_to_film);
  sum.set_attribute("coordination", r.summary.coordination);
  sum.set_attribute("drift", r.summary.drift);
  sum.set_attribute("layering", r.summary.layering);
  sum.set_attribute("layered", static_cast<std::int64_t>(r.summary.layered()));
  for (const auto& o : r.summary.observables) {
    H5Group q = sum.create_group(o.name);
    q.set_attribute("mean", o.estimate.mean);
    q.set_attribute("standard_error", o.estimate.standard_error);
    q.set_attribute("samples", static_cast<std::int64_t>(o.estimate.samples));
    q.set_attribute("block_size", static_cast<std::int64_t>(o.estimate.block_size));
    q.set_attribute("reliable", static_cast<std::int64_t>(o.estimate.reliable));
    q.set_attribute("units", std::string("E*"));
  }

  H5Group c = g.create_group("counters");
  write_counters(c, r.counters);
  if (s.quasi_static) {
    c.set_attribute("stress_drops", static_cast<std::int64_t>(s.quasi_static->stress_drops));
    c.set_attribute("unconverged_steps",
                    static_cast<std::int64_t>(s.quasi_static->unconverged_steps));
  }

  write_configuration(g.create_group("configuration"), s.final_particles, s.final_box);

  if (!r.snapshots.empty()) write_snapshots(g.create_group("snapshots"), r.snapshots);
}

void write_structure(H5Group&& g, const StructureRecord& record) {
  const StructureResult& s = record.result;
  g.set_attribute("snapshots", static_cast<std::int64_t>(s.snapshots));
  g.set_attribute("strain_from", record.strain_from);
  g.set_attribute("strain_to", record.strain_to);
  g.set_attribute("bin_width", s.settings.bin_width);
  g.set_attribute("slab_half_width", s.settings.slab);
  g.set_attribute("map_bin_width", s.settings.map_bin_width);
  g.set_attribute("angle_bins", static_cast<std::int64_t>(s.settings.angle_bins));
  g.set_attribute("batches", static_cast<std::int64_t>(s.settings.batches));
  g.set_attribute("number_density", s.number_density);
  g.write("r", s.r, {}, {"R", "centres of the radial bins"});
  const auto table = [&](const std::array<std::vector<double>, 6>& h) {
    std::vector<double> flat;
    for (const auto& row : h) flat.insert(flat.end(), row.begin(), row.end());
    return flat;
  };
  const std::string order = "rows: g00, g2-2, g2-1, g20, g21, g22";
  g.write("g", table(s.g), {6, s.r.size()},
          {"1", "g_lm(r), real orthonormal harmonics, polar axis z; " + order});
  g.write("g_error", table(s.g_error), {6, s.r.size()},
          {"1", "standard error of g_lm(r) (batch means)"});
  g.write(
      "fg", table(s.fg), {6, s.r.size()},
      {"E* R^2", "force-weighted moments (fg)_lm(r), which rebuild the virial stress; " + order});
  g.write("fg_error", table(s.fg_error), {6, s.r.size()},
          {"E* R^2", "standard error of (fg)_lm(r)"});
  g.write("map_r", s.map_r, {}, {"R", "radial bin centres of g(r, theta)"});
  g.write("map_theta", s.map_theta, {},
          {"rad", "angle from the flow axis x towards the gradient axis y"});
  g.write("map", s.map, {s.map_r.size(), s.map_theta.size()},
          {"1", "g(r, theta) in the flow-gradient plane, pairs with |dz| < slab_half_width"});
  for (const NamedEstimate& e : named_estimates(s)) {
    const double pair[2] = {e.estimate.value, e.estimate.error};
    g.write(e.name, std::span<const double>(pair, 2), {},
            {e.units, std::string(e.meaning) + " [value, standard error]"});
  }
}

std::string now_iso8601() {
  const std::time_t now = std::time(nullptr);
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(now));
}

}  // namespace

FileKind file_kind(const H5Group& root) {
  const auto attribute = [&](const char* name) {
    return root.has_attribute(name) ? root.attribute_string(name) : std::string();
  };
  if (attribute("kind").ends_with("checkpoint")) return FileKind::checkpoint;
  if (attribute("software").starts_with("softglass macro")) return FileKind::macro_result;
  if (root.has_attribute("format_version") ||
      (root.has_child("packing") && attribute("software").starts_with("softglass micro"))) {
    const std::int64_t format =
        root.has_attribute("format_version") ? root.attribute_int("format_version") : 0;
    if (format != kFormatVersion) return FileKind::older_run;
    if (root.has_child("shear")) return FileKind::run;
    if (root.has_child("oscillation")) return FileKind::oscillation_run;
    return FileKind::packing;
  }
  // The tables and the slip runs carry no attribute of their own on the root.
  if (root.has_child("flow_curve") && root.has_child("flow_curve_packings"))
    return FileKind::sweep_table;
  if (root.has_child("oscillation") && root.has_child("oscillation_packings"))
    return FileKind::oscillation_table;
  if (root.has_child("stationary") && root.has_child("profile") && root.has_child("series"))
    return FileKind::slip_run;
  return FileKind::other;
}

std::string describe(FileKind kind) {
  switch (kind) {
    case FileKind::run:
      return "a run file (micro run)";
    case FileKind::packing:
      return "a packing file (micro pack)";
    case FileKind::oscillation_run:
      return "an oscillatory run (micro oscillate)";
    case FileKind::older_run:
      return "a run file of an older format";
    case FileKind::checkpoint:
      return "the checkpoint of an unfinished run (*.checkpoint.h5)";
    case FileKind::sweep_table:
      return "the table of a sweep (micro sweep's flow_curve.h5)";
    case FileKind::oscillation_table:
      return "the table of an oscillation sweep (micro oscillate's oscillation.h5)";
    case FileKind::slip_run:
      return "a run between walls (micro slip's runs/*.h5)";
    case FileKind::macro_result:
      return "a result of macro run or macro compare";
    case FileKind::other:
      break;
  }
  return "an HDF5 file softglass micro did not write";
}

H5File open_micro_file(const std::filesystem::path& path, const std::string& expected) {
  try {
    return H5File::open(path);
  } catch (const InputError&) {
    // A text file (a table, a parameter file) is named as such; for anything
    // else H5File's own message says what is wrong.
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(path, ignored)) throw;
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const bool text = !head.empty() && head.find('\0') == std::string::npos;
    if (!text) throw;
    throw InputError(fmt::format("'{}' is a text file (a table or a parameter file?), not {}",
                                 path.string(), expected));
  }
}

void require_file_kind(const H5Group& root, const std::filesystem::path& path,
                       std::initializer_list<FileKind> accepted, const std::string& expected) {
  const FileKind kind = file_kind(root);
  for (const FileKind k : accepted)
    if (k == kind) return;
  if (kind == FileKind::older_run) {
    const std::int64_t format =
        root.has_attribute("format_version") ? root.attribute_int("format_version") : 0;
    throw InputError(fmt::format(
        "'{}' has run-file format {}, this version reads {} (G0 is now the mean over six "
        "simple shears: rerun the case)",
        path.string(), format, kFormatVersion));
  }
  throw InputError(fmt::format("'{}' is {}, not {}", path.string(), describe(kind), expected));
}

void require_run_file_format(const H5Group& root, const std::filesystem::path& path) {
  require_file_kind(root, path, {FileKind::run, FileKind::packing, FileKind::oscillation_run},
                    "a packing or run file of micro (micro pack, micro run)");
}

void write_run_file(const std::filesystem::path& path, const RunRecord& record) {
  H5File file = H5File::create(path);
  H5Group root = file.root();
  root.set_attribute("software", std::string("softglass micro"));
  root.set_attribute("version", std::string(kVersion));
  root.set_attribute("git_revision", std::string(kGitRevision));
  root.set_attribute("created", now_iso8601());
  root.set_attribute("command", record.command);
  root.set_attribute("format_version", kFormatVersion);
  root.write_string("parameters", record.parameters,
                    {"", "the complete parameter file of the run, defaults included"});

  H5Group t = root.create_group("timings");
  t.write_scalar("packing", record.timings.packing,
                 {"s", "wall time to make and relax the packing"});
  t.write_scalar("shear_modulus", record.timings.modulus, {"s", "wall time for G0"});
  t.write_scalar("shear", record.timings.shear,
                 {"s", "wall time of the sheared run, earlier invocations included"});
  t.write_scalar("resumed", record.timings.resumed,
                 {"s", "part of shear run before the last resume from a checkpoint"});
  t.write_scalar("total", record.timings.total, {"s", "wall time of the command, plus resumed"});
  t.write_scalar("threads", record.timings.threads, {"1", "OpenMP threads"});

  H5Group p = root.create_group("packing");
  write_packing(p, record.packing, record.modulus);
  write_configuration(p.create_group("configuration"), record.packing_particles,
                      record.packing_box);

  if (record.shear) {
    H5Group shear = root.create_group("shear");
    shear.set_attribute("contact_law", record.contact_law.name);
    const std::string coefficients = record.contact_law.coefficients.serialise();
    if (!coefficients.empty()) shear.set_attribute("contact_law_coefficients", coefficients);
    const std::string table = record.contact_law.table();
    if (!table.empty())
      shear.write_string("contact_law_table", table, {"", "the table law's data"});
    write_shear(std::move(shear), *record.shear);
  }
  if (record.oscillation) {
    H5Group oscillation = root.create_group("oscillation");
    oscillation.set_attribute("contact_law", record.contact_law.name);
    write_oscillation(std::move(oscillation), *record.oscillation);
  }
  if (record.structure) write_structure(root.create_group("structure"), *record.structure);
  file.close();
}

StoredPacking read_packing(const std::filesystem::path& path) {
  const H5File file = H5File::open(path);
  const H5Group root = file.root();
  require_run_file_format(root, path);
  const H5Group p = root.group("packing");
  const std::string where = path.string();
  StoredConfiguration configuration = read_configuration(p.group("configuration"), where);
  StoredPacking s;
  s.particles = std::move(configuration.particles);
  s.box = configuration.box;
  const auto number = [&](const char* name) {
    return finite(p.read_scalar(name), where, fmt::format("dataset '/packing/{}'", name));
  };
  const auto whole = [&](const char* name) {
    return count(p.read_scalar(name), where, fmt::format("dataset '/packing/{}'", name));
  };
  PackingReport& r = s.report;
  r.particles = s.particles.size();
  r.volume_fraction = number("volume_fraction");
  r.side = number("side");
  r.coordination = number("coordination");
  r.coordination_nonrattler = number("coordination_nonrattler");
  r.rattlers = whole("rattlers");
  r.mean_deformation = number("mean_deformation");
  r.max_deformation = number("max_deformation");
  r.pressure = number("pressure");
  r.energy_per_particle = number("energy_per_particle");
  r.residual = number("residual");
  r.iterations = whole("iterations");
  r.converged = number("converged") != 0.0;
  s.modulus.modulus = number("shear_modulus");
  s.modulus.flow_gradient_modulus = number("shear_modulus_flow_gradient");
  s.modulus.direction_spread = number("shear_modulus_direction_sd");
  s.modulus.affine_modulus = number("affine_shear_modulus");
  s.modulus.solver_error = number("shear_modulus_solver_error");
  return s;
}

TimeSeries read_time_series(const std::filesystem::path& path) {
  const H5File file = H5File::open(path);
  return read_time_series(file.root().group("shear").group("timeseries"), path.string());
}

StoredRunSummary read_run_summary(const std::filesystem::path& path) {
  const std::string expected =
      "a run file of a sheared packing (micro run, micro sweep's runs/*.h5)";
  const H5File file = open_micro_file(path, expected);
  const H5Group root = file.root();
  require_file_kind(root, path, {FileKind::run}, expected);
  const H5Group packing = root.group("packing");
  const H5Group shear = root.group("shear");
  const H5Group summary = shear.group("summary");
  StoredRunSummary s;
  s.file = path;
  const std::string where = path.string();
  s.packing_fingerprint = configuration_fingerprint(packing.group("configuration"));
  // Every number goes into the flow-curve tables, which refuse NaN and inf.
  const auto positive = [&](const H5Group& g, const char* name) {
    const double v = g.read_scalar(name);
    if (!(v > 0 && std::isfinite(v))) {
      throw InputError(fmt::format("'{}': dataset '{}/{}' = {}; allowed: finite and > 0", where,
                                   g.path(), name, v));
    }
    return v;
  };
  const auto attribute = [&](const H5Group& g, const char* name) {
    return finite(g.attribute_double(name), where,
                  fmt::format("attribute '{}' of '{}'", name, g.path()));
  };
  const std::string protocol =
      shear.has_attribute("protocol") ? shear.attribute_string("protocol") : kOverdamped;
  if (protocol != kOverdamped && protocol != kQuasiStatic) {
    throw InputError(fmt::format("'{}': attribute 'protocol' of '/shear' = '{}'; allowed: {} or {}",
                                 where, protocol, kOverdamped, kQuasiStatic));
  }
  s.quasi_static = protocol == kQuasiStatic;
  if (s.quasi_static) {
    s.gamma_tilde = shear.read_scalar("gamma_tilde");
    if (s.gamma_tilde != 0.0) {
      throw InputError(
          fmt::format("'{}': dataset '/shear/gamma_tilde' = {} in a quasi-static run; "
                      "allowed: 0",
                      where, s.gamma_tilde));
    }
  } else {
    s.gamma_tilde = positive(shear, "gamma_tilde");
  }
  s.volume_fraction = positive(packing, "volume_fraction");
  s.shear_modulus = positive(packing, "shear_modulus");
  s.particles = count(packing.read_scalar("particles"), where, "dataset '/packing/particles'");
  s.converged = summary.attribute_int("converged") != 0;
  s.averaged_strain = attribute(summary, "averaged_strain");
  s.coordination = attribute(summary, "coordination");
  s.layering = attribute(summary, "layering");
  for (const auto& name : shear_observable_names()) {
    const H5Group q = summary.group(name);
    MeanEstimate e;
    e.mean = attribute(q, "mean");
    e.standard_error = attribute(q, "standard_error");
    if (e.standard_error < 0) {
      throw InputError(fmt::format("'{}': attribute 'standard_error' of '{}' = {}; allowed: >= 0",
                                   where, q.path(), e.standard_error));
    }
    e.samples = count(static_cast<double>(q.attribute_int("samples")), where,
                      "attribute 'samples' of '" + q.path() + "'");
    e.block_size = count(static_cast<double>(q.attribute_int("block_size")), where,
                         "attribute 'block_size' of '" + q.path() + "'");
    e.reliable = q.attribute_int("reliable") != 0;
    s.observables.push_back({name, e});
  }
  if (root.has_child("structure")) {
    const H5Group structure = root.group("structure");
    const auto estimate = [&](const char* name) {
      const std::vector<double> a = read_finite(structure, name, where);
      if (a.size() != 2) {
        throw InputError(
            fmt::format("'{}': dataset '/structure/{}' holds {} values; allowed: 2 "
                        "(value, standard error)",
                        where, name, a.size()));
      }
      return Estimate{a[0], a[1]};
    };
    s.r_m = estimate("r_m");
    s.f_m = estimate("f_m");
  }
  return s;
}

}  // namespace softglass::micro

namespace softglass::micro {

StoredSnapshots read_stationary_snapshots(const std::filesystem::path& path) {
  const H5File file = H5File::open(path);
  const H5Group root = file.root();
  if (!root.has_child("shear") || !root.group("shear").has_child("snapshots")) {
    throw InputError(
        fmt::format("'{}' holds no stored configurations (a sheared run with 'snapshot "
                    "interval' > 0 is needed)",
                    path.string()));
  }
  const H5Group shear = root.group("shear");
  const std::string where = path.string();
  StoredSnapshots s;
  s.contact_law.name = shear.attribute_string("contact_law");
  if (shear.has_attribute("contact_law_coefficients"))
    s.contact_law.coefficients =
        ComponentValues::parse(shear.attribute_string("contact_law_coefficients"));
  if (shear.has_child("contact_law_table"))
    s.contact_law.table_text = shear.read_string("contact_law_table");
  const StoredConfiguration configuration = read_configuration(shear.group("configuration"), where);
  s.radius = configuration.particles.radius;
  s.side = configuration.box.side();
  const std::vector<double> strain = read_finite(shear.group("timeseries"), "strain", where);
  if (strain.empty())
    throw InputError(fmt::format("'{}': dataset '/shear/timeseries/strain' is empty", where));
  const double transient = finite(shear.group("summary").attribute_double("transient_strain"),
                                  where, "attribute 'transient_strain' of '/shear/summary'");
  const double stationary_from = strain.front() + transient;

  for (Snapshot& snap : read_snapshots(shear.group("snapshots"), s.radius.size(), where))
    if (snap.strain >= stationary_from - 1e-9) s.snapshots.push_back(std::move(snap));
  return s;
}

void require_structure_replaceable(const std::filesystem::path& path, bool replace) {
  const H5File check = H5File::open(path);
  if (check.root().has_child("structure") && !replace) {
    throw OutputExistsError(fmt::format(
        "'{}' holds a structure analysis already; pass --force to replace it", path.string()));
  }
}

void update_structure(const std::filesystem::path& path, const StructureRecord& structure,
                      bool replace) {
  require_structure_replaceable(path, replace);
  AtomicOutput out(path, /*overwrite=*/true);
  std::filesystem::copy_file(path, out.temporary_path(),
                             std::filesystem::copy_options::overwrite_existing);
  {
    H5File file = H5File::open_for_update(out.temporary_path());
    H5Group root = file.root();
    if (root.has_child("structure")) root.remove_child("structure");
    write_structure(root.create_group("structure"), structure);
    file.close();
  }
  out.commit();
}

}  // namespace softglass::micro
