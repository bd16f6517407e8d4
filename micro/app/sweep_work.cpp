#include "micro/app/sweep_work.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/progress.h"
#include "common/version.h"
#include "micro/app/run_steps.h"
#include "micro/results/flow_curve_table.h"

namespace softglass::micro {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Splits `work` (indices with costs) over the workers: longest first, each to
// the least loaded worker (LPT), the same on every rank.
std::vector<std::size_t> my_share(const std::vector<std::size_t>& work,
                                  const std::vector<double>& cost, const Workers& workers) {
  std::vector<std::size_t> order = work;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<std::size_t>(workers.size()), 0.0);
  std::vector<std::size_t> mine;
  for (std::size_t item : order) {
    const auto least = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[static_cast<std::size_t>(least)] += cost[item];
    if (least == workers.rank()) mine.push_back(item);
  }
  return mine;
}

// Only one sweep per folder; the ranks of this one agree before going on. The
// leader takes the lock into `lock`; when it is refused, the leader throws and
// the others return false.
bool lock_folder(const std::filesystem::path& directory, const Workers& workers,
                 std::optional<DirectoryLock>& lock) {
  std::string lock_error;
  if (workers.leader()) {
    try {
      lock.emplace(directory);
    } catch (const InputError& e) {
      lock_error = e.what();
    }
  }
  if (workers.all(lock_error.empty())) return true;
  if (workers.leader()) throw InputError(lock_error);
  return false;
}

// Makes and measures the packing of `prm` and writes it to `packing.file`.
void make_packing(const MicroParameters& prm, const SweepPacking& packing, const Workers& workers,
                  bool quiet) {
  const auto start = Clock::now();
  std::filesystem::create_directories(packing.file.parent_path());
  AtomicOutput out(packing.file, false);
  RunRecord record = pack_and_measure(prm, make_contact_law(prm.contact_law), "pack", quiet);
  try {
    write_record(out, record, seconds_since(start));
  } catch (const OutputExistsError&) {
    // The tasks of a batch array (--case K) whose cases share this packing
    // make it at once when it is missing. It is one computation of one sweep
    // file, so the copy written first serves them all.
    log(workers, "packing  phi {:.4f} seed {}: written meanwhile by another task, used -> {}",
        packing.volume_fraction, packing.seed, packing.file.string());
    return;
  }
  log(workers, "packing  phi {:.4f} seed {}: Z {:.3f}, G0 {:.4e} E*, {:.1f} s -> {}",
      packing.volume_fraction, packing.seed, record.packing.coordination, record.modulus.modulus,
      seconds_since(start), packing.file.string());
}

// Runs this worker's share of the items not done yet (LPT); one progress bar,
// the leader's, labelled `bar`. A failed item is logged and left out; returns
// how many failed on this worker.
std::size_t run_pending(
    const std::vector<SweepItem>& items, const Workers& workers, bool quiet, const std::string& bar,
    const std::function<void(std::size_t, const std::function<void(double)>&)>& run) {
  std::vector<std::size_t> pending;
  std::vector<double> cost;
  for (std::size_t k = 0; k < items.size(); ++k) {
    cost.push_back(items[k].cost);
    if (!std::filesystem::exists(items[k].file)) pending.push_back(k);
  }
  const std::vector<std::size_t> mine = my_share(pending, cost, workers);
  double total = 0.0, finished = 0.0;
  for (std::size_t k : mine) total += cost[k];
  // Only the leader draws: its share stands for the sweep's time left.
  Progress progress(bar, total, quiet || !workers.leader());
  std::size_t failed = 0;
  for (std::size_t k : mine) {
    // A case resumed from its checkpoint reports its first progress part-way:
    // that part was run before, and must not speed up the time left.
    bool carry = !items[k].checkpoint.empty() && std::filesystem::exists(items[k].checkpoint);
    try {
      run(k, [&](double fraction) {
        if (carry) progress.carry(fraction * cost[k]);
        carry = false;
        progress.update(finished + fraction * cost[k]);
      });
    } catch (const std::exception& e) {
      log(workers, "FAILED   {}: {}", items[k].file.string(), e.what());
      ++failed;
    }
    finished += cost[k];
    progress.update(finished);
  }
  progress.finish();
  return failed;
}

// The packings first: every case of a (φ, seed) starts from its packing.
void make_packings(const CaseSweep& sweep, const Workers& workers) {
  const std::vector<SweepPacking>& packings = sweep.packings();
  std::vector<SweepItem> items;
  for (const SweepPacking& p : packings) items.push_back({p.file, {}, double(sweep.particles())});
  const std::size_t failed =
      run_pending(items, workers, true, "packings", [&](std::size_t k, auto&) {
        make_packing(sweep.packing_parameters(k), packings[k], workers, true);
      });
  if (!workers.all(failed == 0))
    throw NumericalError(
        "some packings failed (see above); a packing refused as not a solid fails again on a "
        "rerun: change its seed or the number of particles");
}

// `--case K` of a batch array: that case alone (and its packing), no lock.
void run_one_case(const CaseSweep& sweep, std::size_t index, const Workers& workers, bool quiet) {
  const std::vector<SweepItem> cases = sweep.cases();
  if (index >= cases.size())
    throw InputError(
        fmt::format("--case {}: the {} has cases 0 … {}", index, sweep.name(), cases.size() - 1));
  const SweepPacking& packing = sweep.packings()[sweep.packing_of(index)];
  if (!std::filesystem::exists(packing.file))
    make_packing(sweep.packing_parameters(sweep.packing_of(index)), packing, workers, quiet);
  if (std::filesystem::exists(cases[index].file)) {
    log(workers, "case {} is done: {}", index, cases[index].file.string());
    return;
  }
  Progress bar("case", 1.0, quiet);
  sweep.run_case(index, workers, [&](double fraction) { bar.update(fraction); });
}

// The pending cases, spread over the workers by cost; a failed case is logged
// and left out, the others go on.
void run_cases(const CaseSweep& sweep, const Workers& workers, bool quiet) {
  const std::size_t failed = run_pending(
      sweep.cases(), workers, quiet, sweep.name(),
      [&](std::size_t k, const auto& progress) { sweep.run_case(k, workers, progress); });
  if (!workers.all(failed == 0) && workers.leader())
    log(workers, "some cases failed; the table holds the others");
  if (failed > 0 && !workers.leader())
    throw NumericalError(fmt::format("{} case(s) failed on rank {}", failed, workers.rank()));
}

}  // namespace

MicroParameters checked_parameters(const std::string& context, double phi, unsigned seed,
                                   const std::function<MicroParameters()>& parameters) {
  try {
    return parameters();
  } catch (const InputError& error) {
    throw InputError(
        fmt::format("{}, phi = {}, packing seed {}: {}", context, phi, seed, error.what()));
  }
}

std::vector<std::string> table_provenance(const std::string& command_line,
                                          const std::string& what) {
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {fmt::format("softglass micro {} ({}), written {}", kVersion, kGitRevision, date),
          fmt::format("command: {}", command_line), what};
}

void write_sweep_tables(const SweepTableFiles& files, const std::string& name,
                        const UnitTable& table, const UnitTable& per_packing,
                        const std::vector<std::string>& provenance) {
  AtomicOutput csv(files.csv, true), packings_csv(files.packings_csv, true), h5(files.h5, true);
  write_table_csv(csv.temporary_path(), files.csv, table, provenance);
  write_table_csv(packings_csv.temporary_path(), files.packings_csv, per_packing, provenance);
  write_tables_h5(h5.temporary_path(), {{name, &table}, {name + "_packings", &per_packing}},
                  provenance);
  AtomicOutput::commit_together({&csv, &packings_csv, &h5});
}

void run_sweep(const CaseSweep& sweep, const SweepOptions& options, const Workers& workers) {
  if (options.list) {
    if (workers.leader()) sweep.print_plan();
    return;
  }
  sweep.check_before_work();
  if (options.only_case) return run_one_case(sweep, *options.only_case, workers, options.quiet);

  std::optional<DirectoryLock> lock;
  if (!lock_folder(sweep.directory(), workers, lock)) return;
  const std::vector<SweepItem> cases = sweep.cases();
  if (!options.gather_only) {
    if (workers.leader()) {
      std::size_t done = 0;
      for (const auto& c : cases) done += std::filesystem::exists(c.file);
      log(workers, "{}", sweep.headline(done, workers));
    }
    make_packings(sweep, workers);
    run_cases(sweep, workers, options.quiet);
  }
  if (!workers.leader()) return;
  const std::size_t missing = sweep.write_tables(workers);
  if (missing > 0)
    throw NumericalError(fmt::format(
        "{} of {} runs are missing; their state points are left out of the table (rerun the "
        "{} to complete it)",
        missing, cases.size(), sweep.name()));
}

}  // namespace softglass::micro
