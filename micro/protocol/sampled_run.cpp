#include "micro/protocol/sampled_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "common/errors.h"
#include "micro/analysis/layering.h"

namespace softglass::micro {

namespace {

class SampledRunner {
 public:
  SampledRunner(OverdampedShear& flow, Integrator& integrator, const SampleSchedule& schedule,
                StopRule& rule, const std::function<void(const ShearProgress&)>& progress,
                const ShearCheckpointing& checkpointing, SampledRun& run)
      : flow_(flow),
        integrator_(&integrator),
        schedule_(schedule),
        rule_(rule),
        progress_(progress),
        checkpointing_(checkpointing),
        run_(run),
        start_(flow.time()),
        next_sample_(start_ + schedule.sample_interval),
        next_check_(start_ + schedule.first_check) {}

  void run() {
    if (const ShearCheckpoint* resume = checkpointing_.resume_from)
      resume_from(*resume);
    else
      start();
    for (;;) {
      if (checkpoint_due()) save_and_restart();
      take_step();
      if (flow_.time() < next_sample_ - slack()) continue;
      record();
      schedule_next_sample();
      if (stops()) break;
    }
    finished_ += segment();
    run_.counters = finished_;
    run_.seconds = seconds();
  }

 private:
  // Clock comparisons: far below a sample interval, far above rounding.
  double slack() const { return 1e-9 * schedule_.sample_interval; }

  double seconds() const {
    return seconds_before_ +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start_).count();
  }

  // The first sample, at the start.
  void start() {
    begin_segment();
    flow_.sample_stress_from(-std::numeric_limits<double>::infinity());
    flow_.evaluate();
    record();
    sample_at(next_sample_);
  }

  void resume_from(const ShearCheckpoint& c) {
    run_.series = c.series;
    run_.snapshots = c.snapshots;
    finished_ = c.counters;
    seconds_before_ = c.seconds;
    restart_from(c);
  }

  // Starting afresh from a checkpoint: a new contact system built from the
  // stored particles, a new integrator, the first evaluation from the stored
  // velocities.
  void restart_from(const ShearCheckpoint& c) {
    const ShearDrive& drive = flow_.drive();
    if (c.amplitude != drive.amplitude() || (!drive.is_steady() && !c.time))
      throw InputError(fmt::format(
          "the checkpoint was written under another drive (strain amplitude {}, this run's {}{})",
          c.amplitude, drive.amplitude(), c.time ? "" : ", and it holds no time"));
    const std::shared_ptr<const ContactLaw> law = flow_.system().shared_law();
    const double skin = flow_.system().neighbours().skin();
    flow_ = OverdampedShear(ContactSystem(c.particles, c.box, law, skin), flow_.model(), drive,
                            c.time.value_or(0.0));
    owned_integrator_ = checkpointing_.new_integrator();
    integrator_ = owned_integrator_.get();
    start_ = c.start;
    next_sample_ = c.next_sample;
    next_check_ = c.next_check;
    next_snapshot_ = c.next_snapshot;
    rule_.worst = c.worst;
    begin_segment();
    sample_at(next_sample_);
    flow_.evaluate();
  }

  bool checkpoint_due() const {
    return checkpointing_.every_steps > 0 &&
           integrator_->stats().accepted - stats_before_.accepted >= checkpointing_.every_steps;
  }

  void save_and_restart() {
    finished_ += segment();
    ShearCheckpoint c{flow_.system().particles(),
                      checkpointed_cell(flow_.system().box()),
                      start_,
                      next_sample_,
                      next_check_,
                      next_snapshot_,
                      rule_.worst,
                      flow_.drive().amplitude(),
                      flow_.time(),
                      run_.series,
                      run_.snapshots,
                      finished_,
                      seconds()};
    if (checkpointing_.save) checkpointing_.save(c);
    restart_from(c);
  }

  void take_step() {
    integrator_->step(flow_, next_sample_ - flow_.time());
    const VelocitySolveStats& solve = flow_.last_solve();
    solver_.fixed_point_sweeps += static_cast<std::size_t>(solve.fixed_point_sweeps);
    solver_.newton_iterations += static_cast<std::size_t>(solve.newton_iterations);
    solver_.cg_iterations += static_cast<std::size_t>(solve.cg_iterations);
  }

  void record() {
    TimeSeries& series = run_.series;
    const StressSample s = flow_.stress();
    series.strain.push_back(flow_.strain());
    series.elastic.push_back(s.elastic);
    series.viscous.push_back(s.viscous);
    series.film.push_back(s.film);
    series.coordination.push_back(2.0 * static_cast<double>(flow_.contact_count()) /
                                  static_cast<double>(flow_.system().size()));
    series.layering.push_back(
        gradient_layering(flow_.system().particles().position, flow_.system().box().side()).order);
    series.step.push_back(integrator_->stats().last_step);
    // Snapshots on the samples nearest to each multiple of the snapshot interval.
    if (schedule_.snapshot_interval > 0.0 &&
        flow_.time() - start_ >= next_snapshot_ - 1e-9 * schedule_.sample_interval) {
      run_.snapshots.push_back({flow_.strain(), flow_.system().wrapped_in_label_order().position});
      next_snapshot_ += schedule_.snapshot_interval;
    }
  }

  // Steps between samples skip the stress (the sample lands exactly on its time).
  void sample_at(double time) { flow_.sample_stress_from(time - slack()); }

  void schedule_next_sample() {
    next_sample_ += schedule_.sample_interval;
    sample_at(next_sample_);
  }

  // The stopping rule at a due check, then the progress report, then the
  // maximum length.
  bool stops() {
    const double elapsed = flow_.time() - start_;
    const bool check_due = flow_.time() >= next_check_ - slack();
    if (check_due) next_check_ += schedule_.check_interval;
    if (rule_.stops(run_.series, check_due, false, run_)) return true;
    if (progress_) progress_({elapsed, schedule_.max_length, rule_.worst});
    const bool at_end = elapsed >= schedule_.max_length - slack();
    return at_end && rule_.stops(run_.series, false, true, run_);
  }

  // The counters of the current segment (since the start or the last
  // checkpoint); `finished_` holds those of the segments before.
  void begin_segment() {
    builds_before_ = flow_.system().neighbours().builds();
    evaluations_before_ = flow_.evaluations();
    stats_before_ = integrator_->stats();
    solver_ = {};
  }

  ShearCounters segment() const {
    const IntegratorStats& stats = integrator_->stats();
    const IntegratorStats& before = stats_before_;
    ShearCounters c = solver_;
    c.steps = stats.accepted - before.accepted;
    c.rejected_steps = stats.rejected - before.rejected;
    c.rejected_error = stats.rejected_error - before.rejected_error;
    c.rejected_list = stats.rejected_list - before.rejected_list;
    c.rejected_solver = stats.rejected_solver - before.rejected_solver;
    c.drag_freezes = stats.drag_freezes - before.drag_freezes;
    c.minimiser = stats.minimiser - before.minimiser;
    c.evaluations = flow_.evaluations() - evaluations_before_;
    c.neighbour_builds = flow_.system().neighbours().builds() - builds_before_;
    c.smallest_step = stats.smallest_step;
    c.largest_step = stats.largest_step;
    return c;
  }

  OverdampedShear& flow_;
  Integrator* integrator_;
  std::unique_ptr<Integrator> owned_integrator_;  // after a restart from a checkpoint
  const SampleSchedule& schedule_;
  StopRule& rule_;
  const std::function<void(const ShearProgress&)>& progress_;
  const ShearCheckpointing& checkpointing_;
  SampledRun& run_;
  const std::chrono::steady_clock::time_point clock_start_ = std::chrono::steady_clock::now();

  double start_;                 // clock at which the run began
  double next_sample_;           // clock of the next sample
  double next_check_;            // clock of the next check
  double next_snapshot_ = 0.0;   // clock since the start of the next snapshot
  double seconds_before_ = 0.0;  // of the run before it was resumed

  ShearCounters finished_, solver_;
  std::size_t builds_before_ = 0, evaluations_before_ = 0;
  IntegratorStats stats_before_;  // the integrator's at the segment's start
};

}  // namespace

void run_sampled(OverdampedShear& flow, Integrator& integrator, const SampleSchedule& schedule,
                 StopRule& rule, const std::function<void(const ShearProgress&)>& progress,
                 const ShearCheckpointing& checkpointing, SampledRun& run) {
  if ((checkpointing.every_steps > 0 || checkpointing.resume_from) && !checkpointing.new_integrator)
    throw std::invalid_argument("run_sampled: checkpoints need new_integrator");
  SampledRunner(flow, integrator, schedule, rule, progress, checkpointing, run).run();
}

}  // namespace softglass::micro
