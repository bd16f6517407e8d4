#include "micro/protocol/quasi_static_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/errors.h"

namespace softglass::micro {

namespace {

// The longest segment (strain): bounds the per-step series run_aqs holds.
constexpr double kMaxSegment = 1.0;
// run_aqs shears at least this many steps (AqsSettings::validate).
constexpr std::size_t kMinSegmentSteps = 20;

// How the strain steps are grouped: into samples, and samples into segments.
struct Layout {
  std::size_t steps_per_sample, samples_per_segment;
  std::size_t min_samples;  // per segment: run_aqs's kMinSegmentSteps
  double spacing;           // strain between samples
};

Layout layout(const QuasiStaticSettings& s, const ShearProtocol& p) {
  Layout l;
  l.steps_per_sample = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::llround(p.sample_interval / s.strain_step)));
  l.spacing = static_cast<double>(l.steps_per_sample) * s.strain_step;
  l.min_samples = (kMinSegmentSteps + l.steps_per_sample - 1) / l.steps_per_sample;
  const double segment =
      std::min(p.snapshot_interval > 0.0 ? p.snapshot_interval : p.check_interval, kMaxSegment);
  l.samples_per_segment = std::max<std::size_t>(
      {1, static_cast<std::size_t>(std::llround(segment / l.spacing)), l.min_samples});
  return l;
}

// Appends the segment's steps to the run: samples (means over their steps),
// stress drops and counters.
void append(const AqsResult& r, const Layout& l, double segment_start,
            QuasiStaticCheckpoint& state) {
  const std::size_t per = l.steps_per_sample;
  const double weight = 1.0 / static_cast<double>(per);
  for (std::size_t first = 0; first + per <= r.steps; first += per) {
    Eigen::Matrix3d elastic = Eigen::Matrix3d::Zero();
    double coordination = 0.0;
    for (std::size_t k = first; k < first + per; ++k) {
      elastic += weight * r.series.elastic[k];
      coordination += weight * r.series.coordination[k];
    }
    state.series.strain.push_back(segment_start + r.series.strain[first + per - 1]);
    state.series.elastic.push_back(elastic);
    state.series.viscous.push_back(Eigen::Matrix3d::Zero());
    state.series.film.push_back(Eigen::Matrix3d::Zero());
    state.series.coordination.push_back(coordination);
    state.series.layering.push_back(0.0);
    state.series.step.push_back(r.series.step[first + per - 1]);
  }
  const bool first_segment = state.counters.steps == 0;
  for (std::size_t k = 0; k < r.steps; ++k) {
    const double sigma = r.series.elastic[k](1, 0);
    if ((k > 0 || !first_segment) && sigma < state.last_sigma) ++state.stress_drops;
    state.last_sigma = sigma;
  }
  state.counters.steps += r.steps;
  state.counters.newton_iterations += r.minimiser.iterations;
  state.counters.cg_iterations += r.minimiser.cg_iterations;
  state.counters.minimiser += r.minimiser;
  state.unconverged_steps += r.unconverged_steps;
}

}  // namespace

double strain_step_of(const QuasiStaticCheckpoint& checkpoint) {
  if (checkpoint.counters.steps == 0) return 0.0;
  return (checkpoint.box.strain() - checkpoint.start) /
         static_cast<double>(checkpoint.counters.steps);
}

QuasiStaticResult run_quasi_static(const Particles& particles, const LeesEdwardsBox& box,
                                   std::shared_ptr<const ContactLaw> law, double skin,
                                   const QuasiStaticSettings& settings,
                                   const ShearProtocol& protocol,
                                   const std::function<void(const ShearProgress&)>& progress,
                                   const QuasiStaticCheckpointing& checkpointing) {
  protocol.validate();
  // Fewer than one step per sample would thin the series below the protocol's
  // 20 samples per stationary window.
  require(settings.strain_step > 0.0 && settings.strain_step <= protocol.sample_interval,
          fmt::format("quasi-static strain step = {} must be in (0, sample interval = {}]",
                      settings.strain_step, protocol.sample_interval));
  const auto clock_start = std::chrono::steady_clock::now();
  const Layout l = layout(settings, protocol);
  // Tolerance of strain comparisons: far below one step, far above rounding.
  const double slack = 1e-6 * settings.strain_step;

  QuasiStaticCheckpoint state;
  if (checkpointing.resume_from) {
    state = *checkpointing.resume_from;
  } else {
    state.particles = particles;
    state.box = checkpointed_cell(box);
    state.start = state.box.strain();
    // No check before the stationary window can exist (nor MSER has its 20 samples).
    state.next_check =
        std::max({protocol.check_interval, protocol.min_strain, protocol.min_stationary_strain});
  }
  const double seconds_before = state.seconds;
  const auto seconds = [&] {
    return seconds_before +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  };

  QuasiStaticResult result;
  ShearResult& run = result.run;
  std::size_t steps_since_save = 0;
  for (;;) {
    const double sheared_before = state.box.strain() - state.start;
    const auto samples_left = static_cast<std::size_t>(
        std::max(0.0, std::ceil((protocol.max_strain - sheared_before - slack) / l.spacing)));
    const std::size_t steps =
        std::max(std::min(l.samples_per_segment, samples_left), l.min_samples) * l.steps_per_sample;

    ContactSystem system(state.particles, state.box, law, skin);
    AqsSettings aqs;
    aqs.strain_step = settings.strain_step;
    aqs.strain = static_cast<double>(steps) * settings.strain_step;
    aqs.min_stationary_strain = aqs.strain;  // the segment's own summary is not used
    aqs.relative_force = settings.relative_force;
    aqs.max_iterations = settings.max_iterations;
    const double segment_start = state.box.strain();
    const AqsResult r = run_aqs(system, aqs);
    append(r, l, segment_start, state);
    state.particles = system.wrapped_in_label_order();
    state.box = checkpointed_cell(system.box());
    if (protocol.snapshot_interval > 0.0)
      state.snapshots.push_back({state.box.strain(), state.particles.position});

    const double sheared = state.box.strain() - state.start;
    const bool check_due = sheared >= state.next_check - slack;
    if (check_due) state.next_check += protocol.check_interval;
    const bool stop = stops_after_sample(state.series, protocol, check_due,
                                         sheared >= protocol.max_strain - slack, run, state.worst);
    if (progress) progress({sheared, protocol.max_strain, state.worst});
    if (stop) break;
    steps_since_save += r.steps;
    if (checkpointing.every_steps > 0 && steps_since_save >= checkpointing.every_steps) {
      steps_since_save = 0;
      state.seconds = seconds();
      if (checkpointing.save) checkpointing.save(state);
    }
  }

  run.series = std::move(state.series);
  run.snapshots = std::move(state.snapshots);
  run.counters = state.counters;
  run.counters.smallest_step = run.counters.largest_step = settings.strain_step;
  run.seconds = seconds();
  result.stress_drops = state.stress_drops;
  result.unconverged_steps = state.unconverged_steps;
  result.final_particles = std::move(state.particles);
  result.final_box = state.box;
  return result;
}

}  // namespace softglass::micro
