#include "micro/app/run_steps.h"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "common/errors.h"
#include "common/memory_budget.h"
#include "common/progress.h"
#include "micro/analysis/shear_modulus.h"
#include "micro/input/finished_work.h"
#include "micro/io/checkpoint_file.h"
#include "micro/results/run_structure.h"

namespace softglass::micro {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A checkpoint to go on from, if its file exists; `read` is the reader of its
// kind. Refused unless it was written by a run of `parameters` (the text the
// run's record stores).
template <class Checkpoint, class Read>
std::optional<Checkpoint> existing_checkpoint(const CheckpointSettings& checkpoints, Read read,
                                              const std::string& parameters) {
  if (checkpoints.file.empty() || !std::filesystem::exists(checkpoints.file)) return std::nullopt;
  try {
    Checkpoint checkpoint = read(checkpoints.file);
    require_checkpoint_of_same_computation(checkpoints.file, parameters);
    return checkpoint;
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} (delete it to start this run afresh)", e.what()));
  }
}

// Checkpointing of a run of `parameters` (ShearCheckpointing or
// QuasiStaticCheckpointing): go on from `resume`, if any, and save into the
// file of `checkpoints`. Both references must outlive the run.
template <class Checkpointing, class Checkpoint>
Checkpointing checkpointing_of(const CheckpointSettings& checkpoints,
                               const std::optional<Checkpoint>& resume,
                               const std::string& parameters) {
  Checkpointing c;
  if (resume) c.resume_from = &*resume;
  if (!checkpoints.file.empty()) {
    c.every_steps = checkpoints.every_steps;
    c.save = [&checkpoints, &parameters](const Checkpoint& state) {
      write_checkpoint(checkpoints.file, state, parameters);
    };
  }
  return c;
}

// The checkpoints of a run of the overdamped dynamics by `scheme` with the
// parameter text `parameters`: saved into the file of `settings`, and resumed
// from it when it exists.
class DynamicsCheckpoints {
 public:
  DynamicsCheckpoints(const CheckpointSettings& settings, const IntegratorSpec& scheme,
                      const std::string& parameters)
      : resume_(existing_checkpoint<ShearCheckpoint>(settings, read_checkpoint, parameters)),
        checkpointing_(checkpointing_of<ShearCheckpointing>(settings, resume_, parameters)) {
    if (!settings.file.empty())
      checkpointing_.new_integrator = [scheme] { return make_integrator(scheme); };
  }
  DynamicsCheckpoints(const DynamicsCheckpoints&) = delete;
  DynamicsCheckpoints& operator=(const DynamicsCheckpoints&) = delete;

  const ShearCheckpointing& checkpointing() const { return checkpointing_; }
  /// Wall time run before the checkpoint resumed from (0 for a fresh run).
  double resumed_seconds() const { return resume_ ? resume_->seconds : 0.0; }

 private:
  std::optional<ShearCheckpoint> resume_;
  ShearCheckpointing checkpointing_;
};

// A run's progress as the commands follow it: (strain, worst relative error).
std::function<void(const ShearProgress&)> follow(
    const std::function<void(double, double)>& progress) {
  return [&progress](const ShearProgress& p) {
    if (progress) progress(p.strain, p.worst_relative_error);
  };
}

// Completes `record` with a finished run: its timings (the part before a
// resume from a checkpoint included), the structure of its stationary part
// when it stored snapshots, and the run itself.
void keep_run(RunRecord& record, ShearRecord&& shear, double resumed_seconds,
              Clock::time_point start, const ContactLaw& law, const MicroParameters& prm) {
  record.timings.resumed = resumed_seconds;
  record.timings.shear = resumed_seconds + seconds_since(start);
  const std::vector<Snapshot> stationary = stationary_snapshots(shear.result);
  if (stationary.size() >= 2) {
    record.structure = analyse_snapshots(stationary, shear.final_particles.radius,
                                         shear.final_box.side(), law, prm.structure);
  }
  record.shear = std::move(shear);
}

}  // namespace

RunRecord pack_and_measure(const MicroParameters& prm, std::shared_ptr<const ContactLaw> law,
                           const std::string& command, bool quiet) {
  // The slope of `micro pack`'s peak resident memory in N
  // (bench/results/memory_per_particle-*.md); a run holds at least that much,
  // so this bound refuses only what cannot fit.
  constexpr double kBytesPerParticle = 7.4e3;
  require_memory(kBytesPerParticle * static_cast<double>(prm.packing.particles),
                 fmt::format("a packing of N = {} particles", prm.packing.particles));
  const auto start = Clock::now();
  RunRecord record;
  record.command = command;
  record.contact_law = prm.contact_law;
  record.parameters = prm.text;
  record.timings.threads = omp_get_max_threads();

  if (!prm.packing_input.empty()) {
    StoredPacking stored = read_packing(prm.packing_input);
    record.packing_particles = std::move(stored.particles);
    record.packing_box = stored.box;
    record.packing = stored.report;
    record.modulus = stored.modulus;
    if (!quiet) std::fprintf(stderr, "packing read from %s\n", prm.packing_input.c_str());
    return record;
  }
  Progress bar("packing", prm.packing.volume_fraction - prm.packing.initial_volume_fraction, quiet);
  Packing packing = make_packing(prm.packing, law, [&](double phi) {
    bar.update(phi - prm.packing.initial_volume_fraction, fmt::format("phi {:.3f}", phi));
  });
  bar.finish();
  record.packing_particles = std::move(packing.particles);
  record.packing_box = packing.box;
  record.packing = packing.report;
  record.timings.packing = seconds_since(start);

  const auto modulus_start = Clock::now();
  ContactSystem system(record.packing_particles, record.packing_box, law, prm.packing.skin);
  record.modulus = shear_modulus(system);
  record.timings.modulus = seconds_since(modulus_start);
  require_solid(record.modulus,
                fmt::format("the packing of N = {} at phi = {} with seed {}", record.packing.particles,
                            prm.packing.volume_fraction, prm.packing.seed));
  return record;
}

void shear_and_analyse(RunRecord& record, const MicroParameters& prm,
                       std::shared_ptr<const ContactLaw> law,
                       const std::function<void(double, double)>& progress,
                       const CheckpointSettings& checkpoints) {
  const auto start = Clock::now();
  ContactSystem system(record.packing_particles, record.packing_box, law, prm.packing.skin);
  OverdampedShear flow(std::move(system), prm.shear_model);
  // `auto` becomes a concrete scheme for this run's rate (integrator.h).
  const IntegratorSpec scheme = prm.integrator.resolved_for(prm.shear_model.gamma_tilde,
                                                            prm.shear_model.drag.stokes.reference);
  const auto integrator = make_integrator(scheme);
  const DynamicsCheckpoints resumable(checkpoints, scheme, record.parameters);
  ShearRecord shear;
  shear.gamma_tilde = prm.shear_model.gamma_tilde;
  shear.integrator = fmt::format("{}, tolerance {}", scheme.name, scheme.tolerance);
  shear.result =
      run_shear(flow, *integrator, prm.protocol, follow(progress), resumable.checkpointing());
  shear.final_particles = flow.system().wrapped_in_label_order();
  shear.final_box = flow.system().box();
  keep_run(record, std::move(shear), resumable.resumed_seconds(), start, *law, prm);
}

void shear_quasi_statically_and_analyse(RunRecord& record, const MicroParameters& prm,
                                        std::shared_ptr<const ContactLaw> law,
                                        const QuasiStaticSettings& settings,
                                        const std::function<void(double, double)>& progress,
                                        const CheckpointSettings& checkpoints) {
  const auto start = Clock::now();
  const std::optional<QuasiStaticCheckpoint> resume = existing_checkpoint<QuasiStaticCheckpoint>(
      checkpoints, read_quasi_static_checkpoint, record.parameters);
  // A run goes on with the step it was made with, so that its record's step is
  // that of every step it took (the default changed from 2e-4 to 1e-3). The
  // parameters above hold the step; this reads it from a checkpoint written
  // before checkpoints kept their parameters.
  if (resume && resume->counters.steps > 0) {
    const double made = strain_step_of(*resume);
    require(std::abs(made - settings.strain_step) <= 1e-6 * settings.strain_step,
            fmt::format("checkpoint {} was made at quasi-static strain step {:.6g}, the run asks "
                        "for {}: set 'quasi-static strain step' = {:.6g} to go on from it, or "
                        "delete it to start this run afresh",
                        checkpoints.file.string(), made, settings.strain_step, made));
  }
  QuasiStaticResult r = run_quasi_static(
      record.packing_particles, record.packing_box, law, prm.packing.skin, settings, prm.protocol,
      follow(progress),
      checkpointing_of<QuasiStaticCheckpointing>(checkpoints, resume, record.parameters));
  ShearRecord shear;
  shear.gamma_tilde = 0.0;
  shear.result = std::move(r.run);
  shear.final_particles = std::move(r.final_particles);
  shear.final_box = r.final_box;
  shear.quasi_static = QuasiStaticRecord{settings.strain_step, settings.relative_force,
                                         r.stress_drops, r.unconverged_steps};
  keep_run(record, std::move(shear), resume ? resume->seconds : 0.0, start, *law, prm);
}

void oscillate(RunRecord& record, const MicroParameters& prm, std::shared_ptr<const ContactLaw> law,
               const OscillationProtocol& protocol,
               const std::function<void(double, double)>& progress,
               const CheckpointSettings& checkpoints) {
  const auto start = Clock::now();
  ShearModel model = prm.shear_model;
  model.gamma_tilde = protocol.peak_gamma_tilde();
  const auto drive = ShearDrive::oscillatory(protocol.amplitude);
  OverdampedShear flow(
      ContactSystem(record.packing_particles, record.packing_box, law, prm.packing.skin), model,
      drive);
  const IntegratorSpec scheme =
      oscillation_integrator(prm.integrator, protocol, prm.shear_model.drag.stokes.reference);
  const auto integrator = make_integrator(scheme);
  const DynamicsCheckpoints resumable(checkpoints, scheme, record.parameters);
  OscillationRecord oscillation;
  oscillation.protocol = protocol;
  oscillation.integrator = fmt::format("{}, tolerance {}", scheme.name, scheme.tolerance);
  const double period = protocol.period();
  oscillation.result = run_oscillation(
      flow, *integrator, protocol,
      [&](const ShearProgress& p) {
        if (progress) progress(p.strain / period, p.worst_relative_error);
      },
      resumable.checkpointing());
  oscillation.final_particles = flow.system().wrapped_in_label_order();
  oscillation.final_box = flow.system().box();
  const double resumed = resumable.resumed_seconds();
  record.timings.resumed = resumed;
  record.timings.shear = resumed + seconds_since(start);
  record.oscillation = std::move(oscillation);
}

void write_record(AtomicOutput& out, RunRecord& record, double total_seconds) {
  record.timings.total = record.timings.resumed + total_seconds;
  write_run_file(out.temporary_path(), record);
  out.commit();
}

std::string logged_time(const RunRecord& record) {
  const Timings& t = record.timings;
  if (t.resumed <= 0.0) return fmt::format("{:.1f} s", t.total);
  return fmt::format("{:.1f} s, resumed from its checkpoint ({:.1f} s of it before)", t.total,
                     t.resumed);
}

}  // namespace softglass::micro
