#include "micro/protocol/shear_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "micro/analysis/layering.h"

namespace softglass::micro {

namespace {

// Strain over which S_y is averaged to decide that a sample has layered.
constexpr double kLayeringWindow = 2.0;

class SteadyShearRun {
 public:
  SteadyShearRun(OverdampedShear& flow, Integrator& integrator, const ShearProtocol& protocol,
                 const std::function<void(const ShearProgress&)>& progress,
                 const ShearCheckpointing& checkpointing)
      : flow_(flow),
        integrator_(&integrator),
        protocol_(protocol),
        progress_(progress),
        checkpointing_(checkpointing),
        start_(flow.strain()),
        next_sample_(start_ + protocol.sample_interval),
        next_check_(start_ + std::max(protocol.check_interval, protocol.min_strain)) {}

  ShearResult run() {
    if (const ShearCheckpoint* resume = checkpointing_.resume_from)
      resume_from(*resume);
    else
      start();
    for (;;) {
      if (checkpoint_due()) save_and_restart();
      take_step();
      if (flow_.strain() < next_sample_ - slack()) continue;
      record();
      schedule_next_sample();
      if (stops()) break;
    }
    finished_ += segment();
    result_.counters = finished_;
    result_.seconds = seconds();
    return std::move(result_);
  }

 private:
  // Strain comparisons: far below a sample interval, far above rounding.
  double slack() const { return 1e-9 * protocol_.sample_interval; }

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
    result_.series = c.series;
    result_.snapshots = c.snapshots;
    finished_ = c.counters;
    seconds_before_ = c.seconds;
    restart_from(c);
  }

  // Starting afresh from a checkpoint: a new contact system built from the
  // stored particles, a new integrator, the first evaluation from the stored
  // velocities.
  void restart_from(const ShearCheckpoint& c) {
    const std::shared_ptr<const ContactLaw> law = flow_.system().shared_law();
    const double skin = flow_.system().neighbours().skin();
    flow_ = OverdampedShear(ContactSystem(c.particles, c.box, law, skin), flow_.model());
    owned_integrator_ = checkpointing_.new_integrator();
    integrator_ = owned_integrator_.get();
    start_ = c.start;
    next_sample_ = c.next_sample;
    next_check_ = c.next_check;
    next_snapshot_ = c.next_snapshot;
    worst_ = c.worst;
    begin_segment();
    sample_at(next_sample_);
    flow_.evaluate();
  }

  bool checkpoint_due() const {
    return checkpointing_.every_steps > 0 &&
           integrator_->stats().accepted - accepted_before_ >= checkpointing_.every_steps;
  }

  void save_and_restart() {
    finished_ += segment();
    const ShearCheckpoint c{flow_.system().particles(),
                            checkpointed_cell(flow_.system().box()),
                            start_,
                            next_sample_,
                            next_check_,
                            next_snapshot_,
                            worst_,
                            result_.series,
                            result_.snapshots,
                            finished_,
                            seconds()};
    if (checkpointing_.save) checkpointing_.save(c);
    restart_from(c);
  }

  void take_step() {
    integrator_->step(flow_, next_sample_ - flow_.strain());
    const VelocitySolveStats& solve = flow_.last_solve();
    solver_.fixed_point_sweeps += static_cast<std::size_t>(solve.fixed_point_sweeps);
    solver_.newton_iterations += static_cast<std::size_t>(solve.newton_iterations);
    solver_.cg_iterations += static_cast<std::size_t>(solve.cg_iterations);
  }

  void record() {
    TimeSeries& series = result_.series;
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
    if (protocol_.snapshot_interval > 0.0 &&
        flow_.strain() - start_ >= next_snapshot_ - 1e-9 * protocol_.sample_interval) {
      result_.snapshots.push_back(
          {flow_.strain(), flow_.system().wrapped_in_label_order().position});
      next_snapshot_ += protocol_.snapshot_interval;
    }
  }

  // Steps between samples skip the stress (the sample lands exactly on its strain).
  void sample_at(double strain) { flow_.sample_stress_from(strain - slack()); }

  void schedule_next_sample() {
    next_sample_ += protocol_.sample_interval;
    sample_at(next_sample_);
  }

  // The stopping rule at a due check (shear_protocol.h) or a layered sample;
  // then the progress report; then the maximum strain.
  bool stops() {
    const double sheared = flow_.strain() - start_;
    const bool check_due = flow_.strain() >= next_check_ - slack();
    if (check_due) next_check_ += protocol_.check_interval;
    if (stops_after_sample(result_.series, protocol_, check_due, false, result_, worst_,
                           [this] { return layered(); }))
      return true;
    if (progress_) progress_({sheared, protocol_.max_strain, worst_});
    const bool at_max = sheared >= protocol_.max_strain - slack();
    return stops_after_sample(result_.series, protocol_, false, at_max, result_, worst_);
  }

  // A sample that has layered is no longer a glass: stop, unconverged.
  std::optional<std::string> layered() const {
    const TimeSeries& series = result_.series;
    const std::size_t window =
        std::min(series.size(),
                 static_cast<std::size_t>(std::ceil(kLayeringWindow / protocol_.sample_interval)));
    double recent = 0.0;
    for (std::size_t k = series.size() - window; k < series.size(); ++k)
      recent += series.layering[k] / window;
    if (recent <= kLayeredThreshold) return std::nullopt;
    return fmt::format(
        "the sample layered under shear (S_y = {:.0f} over the last {} strain, threshold {:.0f})",
        recent, kLayeringWindow, kLayeredThreshold);
  }

  // The counters of the current segment (since the start or the last
  // checkpoint); `finished_` holds those of the segments before.
  void begin_segment() {
    builds_before_ = flow_.system().neighbours().builds();
    evaluations_before_ = flow_.evaluations();
    accepted_before_ = integrator_->stats().accepted;
    rejected_before_ = integrator_->stats().rejected;
    solver_ = {};
  }

  ShearCounters segment() const {
    const IntegratorStats& stats = integrator_->stats();
    ShearCounters c = solver_;
    c.steps = stats.accepted - accepted_before_;
    c.rejected_steps = stats.rejected - rejected_before_;
    c.evaluations = flow_.evaluations() - evaluations_before_;
    c.neighbour_builds = flow_.system().neighbours().builds() - builds_before_;
    c.smallest_step = stats.smallest_step;
    c.largest_step = stats.largest_step;
    return c;
  }

  OverdampedShear& flow_;
  Integrator* integrator_;
  std::unique_ptr<Integrator> owned_integrator_;  // after a restart from a checkpoint
  const ShearProtocol& protocol_;
  const std::function<void(const ShearProgress&)>& progress_;
  const ShearCheckpointing& checkpointing_;
  const std::chrono::steady_clock::time_point clock_start_ = std::chrono::steady_clock::now();

  ShearResult result_;
  double start_;                // strain at which the run began
  double next_sample_;          // strain of the next sample
  double next_check_;           // strain of the next steady-state check
  double next_snapshot_ = 0.0;  // strain since the start of the next snapshot
  double worst_ = std::numeric_limits<double>::infinity();  // at the last check
  double seconds_before_ = 0.0;                             // of the run before it was resumed

  ShearCounters finished_, solver_;
  std::size_t builds_before_ = 0, evaluations_before_ = 0, accepted_before_ = 0,
              rejected_before_ = 0;
};

}  // namespace

ShearResult run_shear(OverdampedShear& flow, Integrator& integrator, const ShearProtocol& protocol,
                      const std::function<void(const ShearProgress&)>& progress,
                      const ShearCheckpointing& checkpointing) {
  protocol.validate();
  if ((checkpointing.every_steps > 0 || checkpointing.resume_from) && !checkpointing.new_integrator)
    throw std::invalid_argument("run_shear: checkpoints need new_integrator");
  return SteadyShearRun(flow, integrator, protocol, progress, checkpointing).run();
}

}  // namespace softglass::micro
