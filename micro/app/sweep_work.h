// What the commands that run many independent cases share — `micro sweep`
// (flow curves) and `micro oscillate` (amplitude and frequency sweeps): the
// log lines, the checks before any work, the tables' provenance and files,
// and the run itself (run_sweep): the folder lock, the packings, the pending
// cases spread over the workers with a progress bar.
//
// Resuming is a consequence of how files are written: each packing and each
// run is written whole under a temporary name and renamed into place, so a
// file that exists is finished and a rerun skips it. The tables are always
// rebuilt from the run files, so an interrupted and resumed sweep ends with the
// tables of an uninterrupted one. A file is reused only if it stores the
// parameters the file now gives (finished_work.h).
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/unit_table.h"
#include "micro/app/workers.h"
#include "micro/input/parameter_file.h"
#include "micro/sweep/directory_lock.h"
#include "micro/sweep/sweep_plan.h"

namespace softglass::micro {

/// One log line per finished piece of work, on stdout, prefixed by the worker.
template <class... Args>
void log(const Workers& workers, fmt::format_string<Args...> format, Args&&... args) {
  const std::string prefix = workers.size() > 1 ? fmt::format("[rank {}] ", workers.rank()) : "";
  fmt::print("{}{}\n", prefix, fmt::format(format, std::forward<Args>(args)...));
  std::fflush(stdout);
}

/// The subsections a packing depends on: a packing found in the folder is
/// reused when these agree (finished_work.h).
inline const std::vector<std::string> kPackingSubsections = {"particles", "packing", "contact law"};

/// `parameters()`, with an InputError of it prefixed by "<context>, phi = …,
/// packing seed …": building every packing's and case's parameters before any
/// work checks them (a value wrong only in combination with the sweep's, such
/// as N = 1, is one message up front instead of one failure per packing).
MicroParameters checked_parameters(const std::string& context, double phi, unsigned seed,
                                   const std::function<MicroParameters()>& parameters);

/// The provenance lines of a sweep's tables: software and date, the command
/// line, and `what` (its size and units).
std::vector<std::string> table_provenance(const std::string& command_line, const std::string& what);

/// A sweep's averaged and per-packing tables as two CSV files and one HDF5
/// file (groups `name` and `name`_packings), put in place together.
struct SweepTableFiles {
  std::filesystem::path csv, packings_csv, h5;
};
void write_sweep_tables(const SweepTableFiles& files, const std::string& name,
                        const UnitTable& table, const UnitTable& per_packing,
                        const std::vector<std::string>& provenance);

/// A case of a sweep: its result file (which marks it done), its checkpoint
/// (empty: none), its estimated cost.
struct SweepItem {
  std::filesystem::path file, checkpoint;
  double cost;
};

/// A sweep of independent cases sharing their packings: what run_sweep needs
/// of one. One implementation per kind of case: the flow curve's
/// (sweep_command.cpp), the oscillation's (oscillate_command.cpp).
class CaseSweep {
 public:
  virtual ~CaseSweep() = default;
  /// "sweep", "oscillate": the progress bar and the messages.
  virtual std::string name() const = 0;
  virtual const std::filesystem::path& directory() const = 0;
  virtual std::size_t particles() const = 0;
  virtual const std::vector<SweepPacking>& packings() const = 0;
  /// The parameters of packing k: what its file stores.
  virtual MicroParameters packing_parameters(std::size_t k) const = 0;
  virtual std::vector<SweepItem> cases() const = 0;
  virtual std::size_t packing_of(std::size_t case_index) const = 0;
  /// Every packing's and case's parameters built and checked (checked_parameters),
  /// and every finished file the computation now asked for (finished_work.h).
  virtual void check_before_work() const = 0;
  virtual void print_plan() const = 0;
  /// The leader's first log line, given how many cases are done.
  virtual std::string headline(std::size_t done, const Workers& workers) const = 0;
  /// Runs case k and writes its record; `progress(fraction)` follows it.
  virtual void run_case(std::size_t k, const Workers& workers,
                        const std::function<void(double)>& progress) const = 0;
  /// The tables from every finished run; returns how many runs are missing.
  virtual std::size_t write_tables(const Workers& workers) const = 0;
};

/// What the command line asks of a sweep.
struct SweepOptions {
  std::filesystem::path parameter_file;
  std::string command_line;              // recorded in the tables
  bool quiet = false;                    // no progress bar (log lines stay)
  bool list = false;                     // print the cases and their state, run nothing
  bool gather_only = false;              // only rebuild the tables from finished runs
  std::optional<std::size_t> only_case;  // batch-array mode: this case alone
};

/// Runs what is missing of `sweep`: with `list` it prints the plan; with
/// `only_case` that case alone (and its packing), without the lock (the other
/// tasks of a batch array share the folder); otherwise, under the folder's
/// lock, the packings first (every case of a (φ, seed) starts from its
/// packing), then the cases spread over the workers — longest first, each to
/// the least loaded worker (LPT), the same split on every rank, a failed case
/// logged and left out — and last the tables. Throws InputError for a bad
/// file or a locked folder, NumericalError when packings or cases failed or
/// runs are missing from the tables.
void run_sweep(const CaseSweep& sweep, const SweepOptions& options, const Workers& workers);

}  // namespace softglass::micro
