#include "micro/protocol/oscillatory_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/errors.h"

namespace softglass::micro {

namespace {

// Fewest samples per cycle: the fifth harmonic needs more than ten.
constexpr unsigned kMinSamplesPerCycle = 16;

// The implicit step's force residual, relative to the mean contact force,
// need not go below a few hundred roundings of a force sum.
constexpr double kFinestSolverTolerance = 1e-13;

// Stops when the cycles are periodic and G′, G″ are known to the target.
class PeriodicRule final : public StopRule {
 public:
  PeriodicRule(const OscillationProtocol& protocol, OscillationResult& result)
      : protocol_(protocol), result_(result) {}

  bool stops(const TimeSeries& series, bool check_due, bool at_end, SampledRun&) override {
    if (!check_due && !at_end) return false;
    result_.cycles = cycle_responses(series, protocol_);
    result_.summary = summarise_cycles(result_.cycles, protocol_.min_periodic_cycles,
                                       protocol_.target_relative_error);
    const PeriodicSummary& s = result_.summary;
    const std::size_t periodic_cycles = s.cycles - s.transient_cycles;
    const bool enough = s.periodic && periodic_cycles >= protocol_.min_periodic_cycles;
    worst = enough ? s.worst_relative_error() : std::numeric_limits<double>::infinity();
    if (enough && worst <= protocol_.target_relative_error) {
      result_.converged = true;
      result_.stop_reason = fmt::format("periodic over {} cycles, SE of G', G'' ≤ {:.3g} |G*|",
                                        periodic_cycles, worst);
      return true;
    }
    if (!at_end) return false;
    result_.stop_reason =
        fmt::format("maximum of {} cycles reached before the target error {} ({}){}",
                    protocol_.max_cycles, protocol_.target_relative_error,
                    enough ? fmt::format("worst {:.3g}", worst)
                           : fmt::format("{} periodic cycles", s.periodic ? periodic_cycles : 0),
                    s.periodic ? "" : fmt::format("; |G*| drifts (|z| = {:.1f})", s.drift));
    return true;
  }

 private:
  const OscillationProtocol& protocol_;
  OscillationResult& result_;
};

}  // namespace

void OscillationProtocol::validate() const {
  require(std::isfinite(amplitude) && amplitude >= 1e-6 && amplitude <= 10.0,
          fmt::format("strain amplitude gamma0 = {} is outside [1e-6, 10]", amplitude));
  require(std::isfinite(frequency) && frequency > 0.0 && frequency <= 1e-2,
          fmt::format("reduced frequency omega~ = {} is outside (0, 1e-2]", frequency));
  require(peak_gamma_tilde() >= 1e-14 && peak_gamma_tilde() <= 1e-1,
          fmt::format("peak shear rate gamma0 omega~ = {:g} is outside [1e-14, 1e-1] (gamma0 = {}, "
                      "omega~ = {})",
                      peak_gamma_tilde(), amplitude, frequency));
  require(samples_per_cycle >= kMinSamplesPerCycle && samples_per_cycle % 4 == 0 &&
              samples_per_cycle <= 4096,
          fmt::format("samples per cycle = {}; allowed: a multiple of 4 in [{}, 4096]",
                      samples_per_cycle, kMinSamplesPerCycle));
  require(min_periodic_cycles >= 2,
          fmt::format("min periodic cycles = {}; allowed: 2 or more", min_periodic_cycles));
  require(min_cycles >= 1 + min_periodic_cycles,
          fmt::format("min cycles = {} leaves fewer than min periodic cycles = {} after the "
                      "start-up cycle",
                      min_cycles, min_periodic_cycles));
  require(
      max_cycles >= min_cycles && max_cycles <= 100000,
      fmt::format("max cycles = {} is outside [min cycles = {}, 100000]", max_cycles, min_cycles));
  require(target_relative_error > 0.0 && target_relative_error < 1.0,
          fmt::format("target relative error = {} is outside (0, 1)", target_relative_error));
}

double OscillationProtocol::period() const {
  return ShearDrive::oscillatory(amplitude).period();
}

std::vector<std::vector<double>> cycle_responses(const TimeSeries& series,
                                                 const OscillationProtocol& protocol) {
  const std::size_t n = protocol.samples_per_cycle;
  const std::size_t complete = series.size() > 0 ? (series.size() - 1) / n : 0;
  const std::vector<double> sigma = series.component("sigma"),
                            elastic = series.component("sigma_elastic"),
                            viscous = series.component("sigma_viscous"),
                            film = series.component("sigma_film"), n1 = series.component("N1"),
                            n2 = series.component("N2"), pressure = series.component("pressure");
  std::vector<std::vector<double>> cycles;
  for (std::size_t c = 0; c < complete; ++c) {
    const auto part = [&](const std::vector<double>& x) {
      return std::span<const double>(x.data() + c * n, n);
    };
    cycles.push_back(cycle_response(
        {part(sigma), part(elastic), part(viscous), part(film), part(n1), part(n2), part(pressure)},
        protocol.amplitude, protocol.frequency));
  }
  return cycles;
}

IntegratorSpec oscillation_integrator(const IntegratorSpec& spec,
                                      const OscillationProtocol& protocol, StokesReference stokes) {
  IntegratorSpec resolved = spec.resolved_for(protocol.peak_gamma_tilde(), stokes);
  const double scale = std::min(1.0, protocol.amplitude);
  resolved.tolerance *= scale;
  resolved.solver_tolerance = std::max(resolved.solver_tolerance * scale, kFinestSolverTolerance);
  return resolved;
}

OscillationResult run_oscillation(OverdampedShear& flow, Integrator& integrator,
                                  const OscillationProtocol& protocol,
                                  const std::function<void(const ShearProgress&)>& progress,
                                  const ShearCheckpointing& checkpointing) {
  protocol.validate();
  if (flow.drive().is_steady() || flow.drive().amplitude() != protocol.amplitude ||
      flow.model().gamma_tilde != protocol.peak_gamma_tilde() || flow.time() != 0.0)
    throw std::invalid_argument(
        "run_oscillation: the flow must be driven by the protocol's oscillation from time 0");
  const double period = protocol.period();
  const SampleSchedule schedule{period / protocol.samples_per_cycle, period,
                                protocol.min_cycles * period, protocol.max_cycles * period, 0.0};
  OscillationResult result;
  PeriodicRule rule(protocol, result);
  run_sampled(flow, integrator, schedule, rule, progress, checkpointing, result);
  return result;
}

}  // namespace softglass::micro
