// `micro oscillate FILE.prm`: packings, then every (φ, seed, ω̃, γ0) case of
// oscillatory shear, then the tables of G′, G″, the higher harmonics and the
// Chebyshev coefficients — resumable, shared out over MPI ranks, one case at a
// time for batch arrays, exactly as `micro sweep` (sweep_command.cpp and
// sweep_work.h say how).
#include "micro/app/oscillate_command.h"

#include <fmt/format.h>

#include <chrono>
#include <map>
#include <tuple>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/progress.h"
#include "micro/app/run_steps.h"
#include "micro/app/sweep_work.h"
#include "micro/input/finished_work.h"
#include "micro/results/oscillation_table.h"

namespace softglass::micro {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Oscillation {
  OscillationParameters parameters;
  OscillationPlan plan;
  std::string command_line;
};

// The parameters of a packing and of a case: what their files store, and what
// a rerun compares them with (finished_work.h). A case runs at its peak rate.
MicroParameters parameters_of(const Oscillation& o, const SweepPacking& packing) {
  return case_parameters(o.parameters.base, {o.plan.particles,
                                             packing.volume_fraction,
                                             o.parameters.base.shear_model.gamma_tilde,
                                             packing.seed,
                                             std::nullopt,
                                             {},
                                             packing.file});
}

MicroParameters parameters_of(const Oscillation& o, const OscillationCase& c) {
  return case_parameters(o.parameters.base,
                         {o.plan.particles, c.volume_fraction, c.protocol.peak_gamma_tilde(),
                          c.seed, std::nullopt, o.plan.packings[c.packing].file, c.file});
}

// The parameter text a case's file stores, headed by its oscillation.
std::string stored_parameters(const OscillationCase& c, const std::string& text) {
  const OscillationProtocol& p = c.protocol;
  return fmt::format(
      "# An oscillatory case of `micro oscillate`: gamma0 = {}, omega~ = {}, {} samples per "
      "cycle, {} to {} cycles, at least {} periodic, target relative error {}; shear/gamma dot "
      "tilde is the peak rate gamma0 omega~, the rest of subsection shear does not apply.\n{}",
      p.amplitude, p.frequency, p.samples_per_cycle, p.min_cycles, p.max_cycles,
      p.min_periodic_cycles, p.target_relative_error, text);
}

template <class Work>
MicroParameters checked_parameters_of(const Oscillation& o, const Work& work) {
  return checked_parameters("oscillation", work.volume_fraction, work.seed,
                            [&] { return parameters_of(o, work); });
}

// Every packing and case checked, and the finished ones the same computation
// (as `micro sweep` does).
void check_cases_before_work(const Oscillation& o) {
  for (const SweepPacking& p : o.plan.packings) {
    const MicroParameters prm = checked_parameters_of(o, p);
    if (std::filesystem::exists(p.file))
      require_same_computation(p.file, prm.text, kPackingSubsections);
  }
  for (const OscillationCase& c : o.plan.cases) {
    const MicroParameters prm = checked_parameters_of(o, c);
    if (std::filesystem::exists(c.file))
      require_same_computation(c.file, stored_parameters(c, prm.text));
  }
}

std::filesystem::path checkpoint_file(const OscillationCase& c) {
  std::filesystem::path file = c.file;
  return file.replace_extension(".checkpoint.h5");
}

// Oscillates one case and writes its record; `progress(fraction)` follows it
// (by cycles, against the maximum: an upper bound).
void run_case(const Oscillation& o, const OscillationCase& c, const Workers& workers,
              const std::function<void(double)>& progress) {
  const auto start = Clock::now();
  const MicroParameters prm = parameters_of(o, c);
  std::filesystem::create_directories(c.file.parent_path());
  AtomicOutput out(c.file, false);
  const std::shared_ptr<const ContactLaw> law = make_contact_law(prm.contact_law);
  RunRecord record = pack_and_measure(prm, law, "oscillate", true);
  record.parameters = stored_parameters(c, record.parameters);
  const CheckpointSettings checkpoints{checkpoint_file(c), o.parameters.spec.checkpoint_steps};
  oscillate(
      record, prm, law, c.protocol,
      [&](double cycles, double) { progress(std::min(1.0, cycles / c.protocol.max_cycles)); },
      checkpoints);
  write_record(out, record, seconds_since(start));
  std::filesystem::remove(checkpoints.file);
  const OscillationResult& r = record.oscillation->result;
  log(workers,
      "run      phi {:.4f} omega~ {:.3e} gamma0 {:.3e} seed {}: G' {:.4e} ± {:.1e}, G'' {:.4e} ± "
      "{:.1e} E*, I3/I1 {:.3f}, {} cycles, {}, {}",
      c.volume_fraction, c.frequency, c.amplitude, c.seed, r.summary["storage"].mean,
      r.summary["storage"].standard_error, r.summary["loss"].mean, r.summary["loss"].standard_error,
      r.summary["intensity_3"].mean, r.summary.cycles, r.converged ? "converged" : "NOT converged",
      logged_time(record));
}

// Reads every finished run and writes the averaged and per-packing tables.
// Returns the number of missing runs (their state points are left out).
std::size_t write_tables(const Oscillation& o, const Workers& workers) {
  std::map<std::tuple<double, double, double>, std::vector<StoredOscillationSummary>> points;
  std::vector<StoredOscillationSummary> runs;
  std::vector<unsigned> seeds;
  std::size_t missing = 0;
  for (const OscillationCase& c : o.plan.cases) {
    if (!std::filesystem::exists(c.file)) {
      ++missing;
      continue;
    }
    runs.push_back(read_oscillation_summary(c.file));
    seeds.push_back(c.seed);
    points[{c.volume_fraction, c.frequency, c.amplitude}].push_back(runs.back());
  }
  std::vector<OscillationAverage> averages;
  for (const auto& [point, point_runs] : points)
    if (point_runs.size() == o.plan.seeds.size())
      averages.push_back(average_oscillations(point_runs));
  write_sweep_tables(
      {o.plan.table_csv, o.plan.packing_table_csv, o.plan.table_h5}, "oscillation",
      oscillation_table(averages), oscillation_packing_table(runs, seeds),
      table_provenance(o.command_line,
                       fmt::format("N = {}, {} packings per volume fraction; moduli in units of "
                                   "E*, v1 and v3 of eta_s",
                                   o.plan.particles, o.plan.seeds.size())));
  log(workers, "table    {} state points ({} runs) -> {}, {}, {}", averages.size(), runs.size(),
      o.plan.table_csv.string(), o.plan.packing_table_csv.string(), o.plan.table_h5.string());
  return missing;
}

void print_plan(const Oscillation& o) {
  const OscillationPlan& plan = o.plan;
  fmt::print(
      "oscillate N = {}, {} volume fractions x {} frequencies x {} amplitudes x {} "
      "packings = {} cases\n",
      plan.particles, plan.volume_fractions.size(), plan.frequencies.size(), plan.amplitudes.size(),
      plan.seeds.size(), plan.cases.size());
  double pending = 0.0;
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const OscillationCase& c = plan.cases[k];
    const bool done = std::filesystem::exists(c.file);
    if (!done) pending += c.cost;
    fmt::print("case {:4d}  phi {:.4f}  omega~ {:.3e}  gamma0 {:.3e}  seed {:3d}  {}  {}\n", k,
               c.volume_fraction, c.frequency, c.amplitude, c.seed, done ? "done   " : "pending",
               c.file.string());
  }
  fmt::print(
      "cost     about {:.3g} core hours pending (cost model: "
      "micro/sweep/oscillation_plan.cpp, within a factor 2)\n",
      pending / 3600.0);
}

// The oscillation sweep as run_sweep sees it.
class OscillationSweep final : public CaseSweep {
 public:
  explicit OscillationSweep(Oscillation o) : o_(std::move(o)) {}

  std::string name() const override { return "oscillate"; }
  const std::filesystem::path& directory() const override { return o_.plan.directory; }
  std::size_t particles() const override { return o_.plan.particles; }
  const std::vector<SweepPacking>& packings() const override { return o_.plan.packings; }
  MicroParameters packing_parameters(std::size_t k) const override {
    return parameters_of(o_, o_.plan.packings[k]);
  }
  std::vector<SweepItem> cases() const override {
    std::vector<SweepItem> items;
    for (const OscillationCase& c : o_.plan.cases)
      items.push_back({c.file, checkpoint_file(c), c.cost});
    return items;
  }
  std::size_t packing_of(std::size_t k) const override { return o_.plan.cases[k].packing; }
  void check_before_work() const override { check_cases_before_work(o_); }
  void print_plan() const override { micro::print_plan(o_); }
  std::string headline(std::size_t done, const Workers& workers) const override {
    return fmt::format("oscillate N = {}, {} cases ({} done), {} workers -> {}", o_.plan.particles,
                       o_.plan.cases.size(), done, workers.size(), o_.plan.directory.string());
  }
  void run_case(std::size_t k, const Workers& workers,
                const std::function<void(double)>& progress) const override {
    micro::run_case(o_, o_.plan.cases[k], workers, progress);
  }
  std::size_t write_tables(const Workers& workers) const override {
    return micro::write_tables(o_, workers);
  }

 private:
  Oscillation o_;
};

}  // namespace

void oscillate_command(const SweepOptions& options, const Workers& workers) {
  // One line for all the ranks an MPI starter interrupts together.
  if (workers.leader())
    set_interruption_notice(
        "micro oscillate: interrupted; run the same command again to resume (finished cases "
        "are kept)");
  Oscillation o;
  o.parameters = read_oscillation_file(options.parameter_file);
  o.plan = make_oscillation_plan(o.parameters.spec);
  o.command_line = options.command_line;
  run_sweep(OscillationSweep(std::move(o)), options, workers);
}

}  // namespace softglass::micro
