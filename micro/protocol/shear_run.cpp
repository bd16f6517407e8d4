#include "micro/protocol/shear_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "micro/analysis/layering.h"

namespace softglass::micro {

namespace {

// Strain over which S_y is averaged to decide that a sample has layered.
constexpr double kLayeringWindow = 2.0;

// The steady-state rule of shear_protocol.h, and a layered sample as the
// protocol's own reason to stop.
class SteadyStateRule final : public StopRule {
 public:
  SteadyStateRule(const ShearProtocol& protocol, ShearResult& result)
      : protocol_(protocol), result_(result) {}

  bool stops(const TimeSeries& series, bool check_due, bool at_end, SampledRun&) override {
    return stops_after_sample(series, protocol_, check_due, at_end, result_, worst,
                              [&] { return layered(series); });
  }

 private:
  // A sample that has layered is no longer a glass: stop, unconverged.
  std::optional<std::string> layered(const TimeSeries& series) const {
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

  const ShearProtocol& protocol_;
  ShearResult& result_;
};

}  // namespace

ShearResult run_shear(OverdampedShear& flow, Integrator& integrator, const ShearProtocol& protocol,
                      const std::function<void(const ShearProgress&)>& progress,
                      const ShearCheckpointing& checkpointing) {
  protocol.validate();
  const SampleSchedule schedule{protocol.sample_interval, protocol.check_interval,
                                std::max(protocol.check_interval, protocol.min_strain),
                                protocol.max_strain, protocol.snapshot_interval};
  ShearResult result;
  SteadyStateRule rule(protocol, result);
  run_sampled(flow, integrator, schedule, rule, progress, checkpointing, result);
  return result;
}

}  // namespace softglass::micro
