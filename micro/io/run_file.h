// The HDF5 record of a `micro pack` or `micro run`: one file per run, documented
// group by group in docs/output.md. Everything needed to reproduce and to judge
// the run is in it: the full parameter set, the software version, timings, the
// packing and its measurements, the sampled stress history, the final
// configuration and the steady-state summary with standard errors.
//
// Units are those of the simulation (docs/physics.md, "Motion"): lengths R (mean radius),
// stresses E*, strain for time; every dataset carries a `units` attribute.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include "common/h5_file.h"
#include "micro/analysis/shear_modulus.h"
#include "micro/analysis/structure.h"
#include "micro/io/oscillation_group.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"

namespace softglass::micro {

struct Timings {
  double packing = 0.0, modulus = 0.0, shear = 0.0, total = 0.0;  // seconds (wall)
  double resumed = 0.0;  // of `shear`, run before the last resume from a checkpoint
  int threads = 1;
};

/// What a quasi-static (AQS) run adds to the record of a sheared run
/// (protocol/quasi_static_run.h).
struct QuasiStaticRecord {
  double strain_step = 0.0, relative_force = 0.0;
  std::size_t stress_drops = 0, unconverged_steps = 0;
};

struct ShearRecord {
  double gamma_tilde = 0.0;  // 0 for a quasi-static run
  ShearResult result;
  Particles final_particles;  // label order
  LeesEdwardsBox final_box;
  std::optional<QuasiStaticRecord> quasi_static{};  // set: protocol "aqs", else "overdamped"
  // Overdamped runs: the integrator used, after `auto` was resolved (e.g.
  // "implicit, tolerance 0.001"); the attribute `integrator` of /shear.
  std::string integrator{};
};

/// The structure of the stationary part of a run and where it came from.
struct StructureRecord {
  StructureResult result;
  double strain_from = 0.0, strain_to = 0.0;  // the snapshots' strain window
};

struct RunRecord {
  std::string command;     // "pack", "run" or "oscillate"
  std::string parameters;  // the complete parameter file, defaults included
  PackingReport packing;
  ShearModulus modulus;
  Particles packing_particles;  // the relaxed packing, label order
  LeesEdwardsBox packing_box;
  std::optional<ShearRecord> shear;
  std::optional<OscillationRecord> oscillation;  // `micro oscillate`
  std::optional<StructureRecord> structure;
  ContactLawSpec contact_law;  // stored so that structure can be analysed again
  Timings timings;
};

/// The HDF5 files softglass writes, told apart by what identifies each (the
/// root's attributes `format_version`, `software`, `kind` and its groups), so
/// that a file handed to a command in place of another is named for what it
/// is instead of being refused with advice that cannot help.
enum class FileKind {
  run,                // a sheared packing: micro run, micro sweep's runs/*.h5
  packing,            // micro pack, micro sweep's packings/*.h5
  oscillation_run,    // micro oscillate's runs/*.h5
  older_run,          // a packing or run file of another run-file format
  checkpoint,         // an unfinished case's *.checkpoint.h5
  sweep_table,        // micro sweep's flow_curve.h5
  oscillation_table,  // micro oscillate's oscillation.h5
  slip_run,           // micro slip's runs/*.h5
  macro_result,       // macro run's results.h5, macro compare's comparison.h5
  other,              // an HDF5 file softglass did not write
};
FileKind file_kind(const H5Group& root);
/// "a packing file (micro pack)", for messages.
std::string describe(FileKind kind);

/// Opens `path`, which should be `expected` ("a run file ..."); InputError
/// naming what it is instead when it is not HDF5 (a text file: a table, a
/// parameter file) or does not exist.
H5File open_micro_file(const std::filesystem::path& path, const std::string& expected);

/// InputError unless the file is of one of the kinds `accepted`: "'F' is a
/// packing file (micro pack), not EXPECTED"; a packing or run file of
/// another format is told to be made again.
void require_file_kind(const H5Group& root, const std::filesystem::path& path,
                       std::initializer_list<FileKind> accepted, const std::string& expected);

/// InputError unless the file's root says it has this version's run-file
/// format (a packing, a sheared or an oscillated run).
void require_run_file_format(const H5Group& root, const std::filesystem::path& path);

/// Writes `record` to `path` (which must not exist or is replaced: the caller
/// decides, see common/atomic_output.h).
void write_run_file(const std::filesystem::path& path, const RunRecord& record);

/// The relaxed packing stored in a run file, to shear it again.
struct StoredPacking {
  Particles particles;
  LeesEdwardsBox box;
  PackingReport report;
  ShearModulus modulus;
};
StoredPacking read_packing(const std::filesystem::path& path);

/// The stress history stored in a run file (for re-analysis).
TimeSeries read_time_series(const std::filesystem::path& path);

/// What a run concluded: its state point and steady-state summary.
struct StoredRunSummary {
  std::filesystem::path file;
  double gamma_tilde = 0.0, volume_fraction = 0.0, shear_modulus = 0.0;  // γ̃ = 0: quasi-static
  bool quasi_static = false;                                             // protocol "aqs"
  std::size_t particles = 0;
  bool converged = false;
  double averaged_strain = 0.0, coordination = 0.0, layering = 0.0;
  std::vector<ObservableEstimate> observables;  // shear_observable_names() order
  std::optional<Estimate> r_m, f_m;             // when the run has /structure
  /// A hash of the packing it started from (its particle positions and
  /// radii): equal for two runs of one packing, a run and its copy included.
  std::uint64_t packing_fingerprint = 0;
};
StoredRunSummary read_run_summary(const std::filesystem::path& path);

/// What structure analysis needs from a run file: the snapshots of its
/// stationary part, the radii, the cell and the contact law.
struct StoredSnapshots {
  std::vector<Snapshot> snapshots;  // stationary part only
  std::vector<double> radius;       // label order
  double side = 0.0;
  ContactLawSpec contact_law;
};
StoredSnapshots read_stationary_snapshots(const std::filesystem::path& path);

/// OutputExistsError if the run file holds a /structure group and `replace` is
/// false: checked before an analysis is computed.
void require_structure_replaceable(const std::filesystem::path& path, bool replace);

/// Writes (or, with `replace`, rewrites) the /structure group of an existing
/// run file; the file is updated through a copy renamed over it, so that a
/// failure leaves it as it was. OutputExistsError if /structure exists and
/// `replace` is false.
void update_structure(const std::filesystem::path& path, const StructureRecord& structure,
                      bool replace);

}  // namespace softglass::micro
