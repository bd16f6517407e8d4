// What the commands that run many independent cases share — `micro sweep`
// (flow curves) and `micro oscillate` (amplitude and frequency sweeps): the
// log lines, the folder lock, the packings, and the pending cases spread over
// the workers with a progress bar. A case's result file marks it done, so a
// rerun skips it (sweep_command.cpp, "Resuming").
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

/// Only one sweep per folder; the ranks of this one agree before going on. The
/// leader takes the lock into `lock`; when it is refused, the leader throws and
/// the others return false.
bool lock_folder(const std::filesystem::path& directory, const Workers& workers,
                 std::optional<DirectoryLock>& lock);

/// The subsections a packing depends on: a packing found in the folder is
/// reused when these agree (finished_work.h).
inline const std::vector<std::string> kPackingSubsections = {"particles", "packing", "contact law"};

/// Makes and measures the packing of `prm` and writes it to `packing.file`.
void make_packing(const MicroParameters& prm, const SweepPacking& packing, const Workers& workers,
                  bool quiet);

/// A case of a sweep: its result file (which marks it done), its checkpoint
/// (empty: none), its estimated cost.
struct SweepItem {
  std::filesystem::path file, checkpoint;
  double cost;
};

/// Runs this worker's share of the items not done yet — longest first, each to
/// the least loaded worker (LPT), the same split on every rank — through
/// `run(k, progress)`, which reports the fraction done of item k. One progress
/// bar, the leader's, labelled `bar` (none if `quiet`). A failed item is logged
/// and left out; returns how many failed on this worker.
std::size_t run_pending(
    const std::vector<SweepItem>& items, const Workers& workers, bool quiet, const std::string& bar,
    const std::function<void(std::size_t, const std::function<void(double)>&)>& run);

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

/// The packings first (every case of a (φ, seed) starts from its packing);
/// `parameters(k)` are packing k's. NumericalError if some failed.
void make_packings(const std::vector<SweepPacking>& packings, std::size_t particles,
                   const std::function<MicroParameters(std::size_t)>& parameters,
                   const Workers& workers);

}  // namespace softglass::micro
