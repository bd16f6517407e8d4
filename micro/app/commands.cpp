#include "micro/app/commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "common/atomic_output.h"
#include "common/csv_writer.h"
#include "common/progress.h"
#include "micro/analysis/layering.h"
#include "micro/app/run_steps.h"
#include "micro/input/parameter_file.h"
#include "micro/io/run_file.h"
#include "micro/io/structure_csv.h"
#include "micro/results/packing_average.h"
#include "micro/results/run_structure.h"

namespace softglass::micro {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void print_packing(const RunRecord& r, const MicroParameters& prm) {
  const PackingReport& k = r.packing;
  fmt::print("packing  N = {}, phi = {:.4f}, L = {:.3f} R, law {}, seed {}\n", k.particles,
             k.volume_fraction, k.side, prm.contact_law.name, prm.packing.seed);
  fmt::print(
      "         Z = {:.3f} (backbone {:.3f}, {} rattlers), <eps> = {:.4f}, max eps = {:.4f}\n",
      k.coordination, k.coordination_nonrattler, k.rattlers, k.mean_deformation, k.max_deformation);
  fmt::print(
      "         Pi = {:.4e} E*, G0 = {:.4e} E* (six shears, sd {:.2e}; x-y {:.4e}; affine "
      "{:.4e}), residual {:.1e}{}\n",
      k.pressure, r.modulus.modulus, r.modulus.direction_spread, r.modulus.flow_gradient_modulus,
      r.modulus.affine_modulus, k.residual, k.converged ? "" : "  NOT CONVERGED");
}

// The implicit steps' work: the frozen drags, and the step solves per solve
// (one per step tried). Empty when the run made none (`euler`).
std::string implicit_cost(const ShearCounters& c) {
  const IncrementalCounters& m = c.minimiser;
  if (m.solves == 0) return "";
  const double solves = double(m.solves);
  return fmt::format(
      "{} drag freezes; {} step solves, each {:.2f} Newton ({:.1f} CG each), {:.2f} force "
      "evaluations, {:.2f} assemblies, {:.3f} damping raises, {:.3f} backtracks; ",
      c.drag_freezes, m.solves, double(m.iterations) / solves,
      double(m.cg_iterations) / double(std::max<std::size_t>(m.iterations, 1)),
      double(m.force_evaluations) / solves, double(m.assemblies) / solves,
      double(m.damping_raises) / solves, double(m.backtracks) / solves);
}

void print_shear(const ShearRecord& s, double particles) {
  const ShearResult& r = s.result;
  const ShearSummary& m = r.summary;
  fmt::print("shear    gamma~ = {:.3e}: {:.2f} strain, transient {:.2f}, averaged {:.2f}\n",
             s.gamma_tilde, r.series.strain.back() - r.series.strain.front(), m.transient_strain,
             m.averaged_strain);
  fmt::print("         {}: {}\n", r.converged ? "converged" : "NOT CONVERGED", r.stop_reason);
  fmt::print("         {:<8} {:>12} {:>10} {:>7}   {:>12} {:>12}\n", "(E*)", "total", "std.err",
             "rel.", "elastic", "viscous");
  for (const char* base : {"sigma", "N1", "N2", "pressure"}) {
    const std::string b(base);
    const MeanEstimate& t = m[b];
    fmt::print("         {:<8} {:>12.5e} {:>10.2e} {:>6.1f}%   {:>12.5e} {:>12.5e}\n", b, t.mean,
               t.standard_error, t.mean != 0 ? 100 * std::abs(t.standard_error / t.mean) : 0.0,
               m[b + "_elastic"].mean, m[b + "_viscous"].mean);
  }
  const ShearCounters& c = r.counters;
  fmt::print(
      "         sigma^e/sigma^v = {:.1f} (films alone {:.1f}), Z = {:.3f}, layering S_y = {:.1f}, "
      "drift |z| = {:.1f}\n",
      m.elastic_to_viscous, m.elastic_to_film, m.coordination, m.layering, m.drift);
  if (m.layered()) {
    fmt::print(
        "WARNING  the sample has layered under shear (S_y = {:.0f} > {:.0f}): these are the "
        "stresses of sliding layers, not of a glass; use more particles or a wider radius "
        "distribution\n",
        m.layering, kLayeredThreshold);
  }
  // The implicit scheme solves for the velocities only where the stress is
  // sampled (backward_euler.cpp): the velocity solver's counts are per such
  // evaluation, the step solves' per step tried, the throughput per step tried.
  const double evaluations = double(std::max<std::size_t>(c.evaluations, 1));
  fmt::print(
      "cost     {} steps ({} rejected: {} error, {} list, {} solver), {} list builds; {} "
      "evaluations, each {:.2f} fixed-point sweeps, {:.2f} Newton and {:.2f} CG iterations; "
      "{}{:.1f} s, {:.3g} particle-steps/s\n",
      c.steps, c.rejected_steps, c.rejected_error, c.rejected_list, c.rejected_solver,
      c.neighbour_builds, c.evaluations, double(c.fixed_point_sweeps) / evaluations,
      double(c.newton_iterations) / evaluations, double(c.cg_iterations) / evaluations,
      implicit_cost(c), r.seconds,
      particles * double(c.steps + c.rejected_steps) / std::max(r.seconds, 1e-9));
}

void print_structure(const StructureRecord& record) {
  const StructureResult& s = record.result;
  fmt::print(
      "structure {} snapshots (strain {:.1f} to {:.1f}): r_m = {:.4f} ± {:.4f} R, "
      "f_m = {:.4e} E*R², Sigma_m = {:.4e} / R²\n",
      s.snapshots, record.strain_from, record.strain_to, s.r_m.value, s.r_m.error, s.f_m.value,
      s.sigma_m.value);
  fmt::print(
      "          sigma^e: virial {:.5e} ± {:.1e}, rebuilt from the structure {:.5e}, "
      "from g_2-2 and the mean-radius force {:.5e}, f_m Sigma_m {:.5e} ± {:.1e}\n",
      s.sigma_virial.value, s.sigma_virial.error, s.sigma_rebuilt.value, s.sigma_law.value,
      s.fm_sigma_m.value, s.fm_sigma_m.error);
}

void finish(RunRecord& record, AtomicOutput& out, Clock::time_point start) {
  write_record(out, record, seconds_since(start));
  fmt::print("written  {}\n", out.final_path().string());
}

}  // namespace

void pack_command(const CommandOptions& options) {
  const auto start = Clock::now();
  const MicroParameters prm = read_parameter_file(options.parameter_file);
  AtomicOutput out(options.output.value_or(prm.output_file), prm.overwrite || options.force);
  RunRecord record =
      pack_and_measure(prm, make_contact_law(prm.contact_law), "pack", options.quiet);
  print_packing(record, prm);
  finish(record, out, start);
}

void run_command(const CommandOptions& options) {
  const auto start = Clock::now();
  const MicroParameters prm = read_parameter_file(options.parameter_file);
  AtomicOutput out(options.output.value_or(prm.output_file), prm.overwrite || options.force);
  const std::shared_ptr<const ContactLaw> law = make_contact_law(prm.contact_law);
  RunRecord record = pack_and_measure(prm, law, "run", options.quiet);
  print_packing(record, prm);

  Progress bar("shear", prm.protocol.max_strain, options.quiet);
  shear_and_analyse(record, prm, law, [&](double strain, double worst) {
    bar.update(strain, fmt::format("strain {:.2f}, worst rel. error {:.3g}", strain, worst));
  });
  bar.finish();
  print_shear(*record.shear, static_cast<double>(record.packing.particles));
  if (record.structure) print_structure(*record.structure);
  finish(record, out, start);
}

void analyze_command(const AnalyzeOptions& options) {
  // Every output is claimed before the analysis, so that a refusal (exit 3)
  // leaves nothing written.
  const StoredSnapshots stored = read_stationary_snapshots(options.run_file);
  require_structure_replaceable(options.run_file, options.force);
  std::optional<StructureCsv> csv;
  if (!options.csv_prefix.empty()) csv.emplace(options.csv_prefix, options.force);
  StructureSettings settings;  // defaults, overridden by the options
  if (options.bin_width) settings.bin_width = *options.bin_width;
  if (options.slab) settings.slab = *options.slab;
  const auto law = make_contact_law(stored.contact_law);
  const StructureRecord record =
      analyse_snapshots(stored.snapshots, stored.radius, stored.side, *law, settings);
  if (csv) csv->write(record);
  update_structure(options.run_file, record, options.force);
  print_structure(record);
  fmt::print("written  {} (/structure){}\n", options.run_file.string(),
             options.csv_prefix.empty() ? "" : ", " + options.csv_prefix + "_*.csv");
}

void summary_command(const std::vector<std::filesystem::path>& runs,
                     const std::filesystem::path& csv, bool force) {
  std::optional<AtomicOutput> out;
  if (!csv.empty()) out.emplace(csv, force);  // refuse early, before reading
  std::vector<StoredRunSummary> summaries;
  for (const auto& file : runs) summaries.push_back(read_run_summary(file));
  const PackingAverage a = average_over_packings(summaries);

  fmt::print(
      "phi = {:.4f}, gamma~ = {:.4e}, N = {}: {} packings ({} converged), {:.1f} strain "
      "averaged in all\n",
      a.volume_fraction, a.gamma_tilde, a.particles, a.runs, a.converged_runs, a.averaged_strain);
  fmt::print("G0 = {:.5e} ± {:.2e} E*\n", a.shear_modulus, a.shear_modulus_error);
  fmt::print("{:<18} {:>13} {:>10} {:>7} {:>10} {:>10}\n", "observable (E*)", "mean", "std.err",
             "rel.", "within", "between");
  for (const auto& o : a.observables) {
    fmt::print("{:<18} {:>13.5e} {:>10.2e} {:>6.1f}% {:>10.2e} {:>10.2e}\n", o.name, o.mean,
               o.standard_error(), o.mean != 0 ? 100 * std::abs(o.standard_error() / o.mean) : 0.0,
               o.within, o.between);
  }
  const double viscous = a["sigma_viscous"].mean, film = a["sigma_film"].mean;
  if (viscous != 0.0) {
    fmt::print("sigma^e/sigma^v = {:.1f} (films alone {:.1f})\n", a["sigma_elastic"].mean / viscous,
               film != 0.0 ? a["sigma_elastic"].mean / film : 0.0);
  }
  for (const auto& run : summaries) {
    if (run.layering > kLayeredThreshold) {
      fmt::print("WARNING  {} has layered under shear (S_y = {:.0f})\n", run.file.string(),
                 run.layering);
    }
  }

  if (out) {
    CsvWriter table(out->final_path().string(),
                    {"observable", "mean [E*]", "standard_error [E*]", "within_runs [E*]",
                     "between_packings [E*]"},
                    {});
    table.may_be_na("within_runs");  // n/a with one run, or one packing
    table.may_be_na("between_packings");
    for (const auto& o : a.observables) {
      table << o.name << o.mean << o.standard_error() << o.within << o.between;
      table.end_row();
    }
    out->write_and_commit([&](std::ostream& f) { f << table.text(); });
    fmt::print("written  {}\n", out->final_path().string());
  }
}

}  // namespace softglass::micro
