// `micro sweep FILE.prm`: packings, then every (φ, γ̃, seed) case and the
// quasi-static (γ̃ = 0) case of every (φ, seed), then the flow-curve table —
// resumable, shared out over MPI ranks, one case at a time for batch arrays.
//
// Resuming is a consequence of how files are written: each packing and each
// run is written whole under a temporary name and renamed into place, so a
// file that exists is finished and a rerun skips it. The table is always
// rebuilt from the run files, so an interrupted and resumed sweep ends with the
// table of an uninterrupted one. A file is reused only if it stores the
// parameters the sweep file now gives (finished_work.h).
#include "micro/app/sweep_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <utility>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"
#include "common/progress.h"
#include "common/version.h"
#include "micro/app/run_steps.h"
#include "micro/app/sweep_work.h"
#include "micro/input/finished_work.h"
#include "micro/results/flow_curve_table.h"
#include "micro/sweep/directory_lock.h"

namespace softglass::micro {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Sweep {
  SweepParameters parameters;
  SweepPlan plan;
  std::string command_line;
};

SweepCaseSettings settings_of(const Sweep& sweep, double phi, unsigned seed, double rate) {
  return {sweep.plan.particles, phi, rate, seed, sweep.plan.run, {}, {}};
}

// The parameters of a packing and of a case: what their files store, and what
// a rerun compares them with (finished_work.h).
MicroParameters parameters_of(const Sweep& sweep, const SweepPacking& packing) {
  SweepCaseSettings settings = settings_of(sweep, packing.volume_fraction, packing.seed,
                                           sweep.parameters.base.shear_model.gamma_tilde);
  settings.output = packing.file;
  return case_parameters(sweep.parameters.base, settings);
}

MicroParameters parameters_of(const Sweep& sweep, const SweepCase& c) {
  // The quasi-static case takes the file's γ̃, which its parameters must hold
  // but nothing uses: its record says protocol aqs and γ̃ = 0.
  SweepCaseSettings settings =
      settings_of(sweep, c.volume_fraction, c.seed,
                  c.quasi_static ? sweep.parameters.base.shear_model.gamma_tilde : c.gamma_tilde);
  settings.packing_input = sweep.plan.packings[c.packing].file;
  settings.output = c.file;
  return case_parameters(sweep.parameters.base, settings);
}

QuasiStaticSettings quasi_static_settings(const Sweep& sweep) {
  return {.strain_step = sweep.plan.quasi_static_strain_step,
          .relative_force = sweep.plan.quasi_static_force_tolerance};
}

// The parameter text a case's run file stores: the quasi-static case's heads
// it with what the file's entries do not say, its strain step and its
// minimiser's tolerance among them.
std::string stored_parameters(const SweepCase& c, const std::string& text,
                              const QuasiStaticSettings& settings) {
  if (!c.quasi_static) return text;
  return fmt::format(
      "# The quasi-static (AQS) case of a sweep: strain step {}, minimiser force tolerance {}; "
      "the stopping rule of subsection shear applies, its gamma dot tilde, the drag and the "
      "integrator do not.\n{}",
      settings.strain_step, settings.relative_force, text);
}

// The strain step and force tolerance a finished run of case `c` must have
// been made with for the sweep to keep it: the sweep's own, or, for a
// quasi-static run made at a finer step or a tighter tolerance, those. Such a
// run resolves at least what the sweep asks for: a tighter tolerance leaves
// each step's stress closer to its minimum's, and the step of the default
// (1e-3) and the former one (2e-4) give the same σ_y, N1, N2 within their
// errors (docs/sweeps.md, "Strain step"). So folders made before a default
// was loosened resume without recomputing.
QuasiStaticSettings kept_quasi_static_settings(const Sweep& sweep, const SweepCase& c) {
  QuasiStaticSettings asked = quasi_static_settings(sweep);
  if (!c.quasi_static) return asked;
  try {
    const H5File file = H5File::open(c.file);
    const H5Group shear = file.root().group("shear");
    const double step = shear.attribute_double("strain_step");
    const double force = shear.attribute_double("relative_force");
    if (step > 0.0 && step < asked.strain_step) asked.strain_step = step;
    if (force > 0.0 && force < asked.relative_force) asked.relative_force = force;
    return asked;
  } catch (const InputError&) {
    // No such record: require_same_computation says what is wrong.
    return quasi_static_settings(sweep);
  }
}

// Before any work: every packing's and case's parameters are built and
// checked (sweep_work.h), and every packing and run already in the folder must
// be the computation the sweep file now asks for; a changed contact law, N or
// run length is refused rather than mixed into the table.
template <class Work>
MicroParameters checked_parameters_of(const Sweep& sweep, const Work& work) {
  return checked_parameters("sweep", work.volume_fraction, work.seed,
                            [&] { return parameters_of(sweep, work); });
}

void check_cases_before_work(const Sweep& sweep) {
  for (const SweepPacking& p : sweep.plan.packings) {
    const MicroParameters prm = checked_parameters_of(sweep, p);
    if (std::filesystem::exists(p.file))
      require_same_computation(p.file, prm.text, kPackingSubsections);
  }
  for (const SweepCase& c : sweep.plan.cases) {
    const MicroParameters prm = checked_parameters_of(sweep, c);
    if (std::filesystem::exists(c.file))
      require_same_computation(
          c.file, stored_parameters(c, prm.text, kept_quasi_static_settings(sweep, c)));
  }
}

// The core seconds of a case by the plan's cost model (per 5 strain,
// docs/sweeps.md) at the runs' shortest length. The model is fitted to the
// default model's whole `paper` sweep (fixed run length): there it is the
// expected time; runs that go on past their shortest length (a target error)
// take longer.
double modelled_seconds(const Sweep& sweep, const SweepCase& c) {
  const double strain =
      sweep.plan.run ? sweep.plan.run->min_strain : sweep.parameters.base.protocol.min_strain;
  return c.cost * std::max(strain, 1.0) / 5.0;
}

double modelled_core_seconds(const Sweep& sweep, bool pending_only) {
  double seconds = 0.0;
  for (const SweepCase& c : sweep.plan.cases)
    if (!pending_only || !std::filesystem::exists(c.file)) seconds += modelled_seconds(sweep, c);
  return seconds;
}

// The wall time of the cases not yet done, spread over the workers.
double estimated_hours(const Sweep& sweep, std::size_t workers) {
  return modelled_core_seconds(sweep, true) / static_cast<double>(workers) / 3600.0;
}

// The cost model was fitted on one machine; the cases this folder has
// finished say how fast this one is (and its threads per case). Their wall
// times as their records keep them (resumed parts included) over their
// modelled times, with how many there were; {0, 0} before the first.
std::pair<double, std::size_t> pace_of_finished_cases(const Sweep& sweep) {
  double measured = 0.0, modelled = 0.0;
  std::size_t finished = 0;
  for (const SweepCase& c : sweep.plan.cases) {
    if (!std::filesystem::exists(c.file)) continue;
    try {
      measured += H5File::open(c.file).root().group("timings").read_scalar("total");
    } catch (const std::exception&) {
      continue;  // a record without timings says nothing of the pace
    }
    modelled += modelled_seconds(sweep, c);
    ++finished;
  }
  return {finished > 0 ? measured / modelled : 0.0, finished};
}

// Where a running case keeps its checkpoint: beside its result file.
std::filesystem::path checkpoint_file(const SweepCase& c) {
  std::filesystem::path file = c.file;
  return file.replace_extension(".checkpoint.h5");
}

// The rate of a case as the log and the list show it.
std::string rate_text(const SweepCase& c) {
  return c.quasi_static ? "0 (AQS)  " : fmt::format("{:.3e}", c.gamma_tilde);
}

// Shears one case — at its rate, or quasi-statically — and writes its record;
// `progress(fraction)` follows it (by strain, an upper bound).
void run_case(const Sweep& sweep, const SweepCase& c, const Workers& workers,
              const std::function<void(double)>& progress) {
  const auto start = Clock::now();
  const MicroParameters prm = parameters_of(sweep, c);
  std::filesystem::create_directories(c.file.parent_path());
  AtomicOutput out(c.file, false);
  const std::shared_ptr<const ContactLaw> law = make_contact_law(prm.contact_law);
  RunRecord record = pack_and_measure(prm, law, "run", true);
  const CheckpointSettings checkpoints{checkpoint_file(c), sweep.parameters.spec.checkpoint_steps};
  const auto follow = [&](double strain, double) {
    progress(std::min(1.0, strain / prm.protocol.max_strain));
  };
  record.parameters = stored_parameters(c, record.parameters, quasi_static_settings(sweep));
  if (c.quasi_static) {
    shear_quasi_statically_and_analyse(record, prm, law, quasi_static_settings(sweep), follow,
                                       checkpoints);
  } else {
    shear_and_analyse(record, prm, law, follow, checkpoints);
  }
  write_record(out, record, seconds_since(start));
  std::filesystem::remove(checkpoints.file);
  const ShearResult& r = record.shear->result;
  const auto& aqs = record.shear->quasi_static;
  log(workers,
      "run      phi {:.4f} gamma~ {} seed {}: sigma {:.4e} ± {:.1e} E*, {:.1f} strain, {}{}{}, "
      "{}",
      c.volume_fraction, rate_text(c), c.seed, r.summary["sigma"].mean,
      r.summary["sigma"].standard_error, r.series.strain.back() - r.series.strain.front(),
      r.converged ? "converged" : "NOT converged", r.summary.layered() ? " (LAYERED)" : "",
      aqs && aqs->unconverged_steps > 0
          ? fmt::format(" ({} of {} strain steps not minimised to tolerance)",
                        aqs->unconverged_steps, r.counters.steps)
          : "",
      logged_time(record));
}

std::vector<std::string> provenance(const Sweep& sweep) {
  return table_provenance(
      sweep.command_line,
      fmt::format("preset {}, N = {}, {} packings per volume fraction; stresses in units of E*",
                  sweep.parameters.spec.preset, sweep.plan.particles, sweep.plan.seeds.size()));
}

// Reads every finished run and writes the averaged and per-packing tables.
// Returns the number of missing runs (their state points are left out).
std::size_t write_tables(const Sweep& sweep, const Workers& workers) {
  std::map<std::pair<double, double>, std::vector<StoredRunSummary>> points;
  std::vector<StoredRunSummary> runs;
  std::vector<unsigned> seeds;
  std::size_t missing = 0;
  for (const SweepCase& c : sweep.plan.cases) {
    if (!std::filesystem::exists(c.file)) {
      ++missing;
      continue;
    }
    runs.push_back(read_run_summary(c.file));
    seeds.push_back(c.seed);
    points[{c.volume_fraction, c.gamma_tilde}].push_back(runs.back());
  }
  std::vector<PackingAverage> averages;
  for (const auto& [point, point_runs] : points) {
    if (point_runs.size() == sweep.plan.seeds.size())
      averages.push_back(average_over_packings(point_runs));
  }
  const UnitTable table = flow_curve_table(averages);
  const UnitTable per_packing = per_packing_table(runs, seeds);
  write_sweep_tables({sweep.plan.table_csv, sweep.plan.packing_table_csv, sweep.plan.table_h5},
                     "flow_curve", table, per_packing, provenance(sweep));
  log(workers, "table    {} state points ({} runs) -> {}, {}, {}", averages.size(), runs.size(),
      sweep.plan.table_csv.string(), sweep.plan.packing_table_csv.string(),
      sweep.plan.table_h5.string());
  return missing;
}

void print_plan(const Sweep& sweep) {
  const SweepPlan& plan = sweep.plan;
  fmt::print(
      "sweep    preset {}, N = {}, {} volume fractions x {} rates{} x {} packings = {} cases\n",
      sweep.parameters.spec.preset, plan.particles, plan.volume_fractions.size(),
      plan.gamma_tildes.size(), plan.quasi_static ? " (+ quasi-static)" : "", plan.seeds.size(),
      plan.cases.size());
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const SweepCase& c = plan.cases[k];
    fmt::print("case {:4d}  phi {:.4f}  gamma~ {}  seed {:3d}  {}  {}\n", k, c.volume_fraction,
               rate_text(c), c.seed, std::filesystem::exists(c.file) ? "done   " : "pending",
               c.file.string());
  }
  // The cost model's figures, which bench/sweep_cost.sh scales a measured
  // slice by to estimate a whole sweep.
  fmt::print(
      "cost     {:.4g} core hours for all cases, {:.4g} for those pending (cost model, "
      "docs/sweeps.md)\n",
      modelled_core_seconds(sweep, false) / 3600.0, modelled_core_seconds(sweep, true) / 3600.0);
}

// The flow-curve sweep as run_sweep sees it.
class FlowCurveSweep final : public CaseSweep {
 public:
  explicit FlowCurveSweep(Sweep sweep) : sweep_(std::move(sweep)) {}

  std::string name() const override { return "sweep"; }
  const std::filesystem::path& directory() const override { return sweep_.plan.directory; }
  std::size_t particles() const override { return sweep_.plan.particles; }
  const std::vector<SweepPacking>& packings() const override { return sweep_.plan.packings; }
  MicroParameters packing_parameters(std::size_t k) const override {
    return parameters_of(sweep_, sweep_.plan.packings[k]);
  }
  std::vector<SweepItem> cases() const override {
    std::vector<SweepItem> items;
    for (const SweepCase& c : sweep_.plan.cases)
      items.push_back({c.file, checkpoint_file(c), c.cost});
    return items;
  }
  std::size_t packing_of(std::size_t k) const override { return sweep_.plan.cases[k].packing; }
  void check_before_work() const override { check_cases_before_work(sweep_); }
  void print_plan() const override { micro::print_plan(sweep_); }
  std::string headline(std::size_t done, const Workers& workers) const override {
    const SweepPlan& plan = sweep_.plan;
    const double hours = estimated_hours(sweep_, workers.size());
    const auto [pace, finished] = pace_of_finished_cases(sweep_);
    return fmt::format(
        "sweep    preset {}, N = {}, {} cases ({} done), {} workers -> {}; estimated {:.2g} h "
        "at the runs' shortest length (cost model, docs/sweeps.md){}",
        sweep_.parameters.spec.preset, plan.particles, plan.cases.size(), done, workers.size(),
        plan.directory.string(), hours,
        finished > 0 && done < plan.cases.size()
            ? fmt::format(", {:.2g} h at this machine's pace (the {} finished case{} took x{:.3g} "
                          "the model's time)",
                          hours * pace, finished, finished == 1 ? "" : "s", pace)
            : "");
  }
  void run_case(std::size_t k, const Workers& workers,
                const std::function<void(double)>& progress) const override {
    micro::run_case(sweep_, sweep_.plan.cases[k], workers, progress);
  }
  std::size_t write_tables(const Workers& workers) const override {
    return micro::write_tables(sweep_, workers);
  }

 private:
  Sweep sweep_;
};

}  // namespace

void sweep_command(const SweepOptions& options, const Workers& workers) {
  // One line for all the ranks an MPI starter interrupts together.
  if (workers.leader())
    set_interruption_notice(
        "micro sweep: interrupted; run the same command again to resume (finished cases are "
        "kept)");
  Sweep sweep;
  sweep.parameters = read_sweep_file(options.parameter_file);
  sweep.plan = make_sweep_plan(sweep.parameters.spec);
  sweep.command_line = options.command_line;
  run_sweep(FlowCurveSweep(std::move(sweep)), options, workers);
}

}  // namespace softglass::micro
