#include "common/measured_curves.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <utility>

#include "common/errors.h"
#include "common/measured/layout.h"
#include "common/measured/registered_layouts.h"

namespace softglass {

namespace measured {

#define SOFTGLASS_DECLARE_LAYOUT(name) LayoutEntry name##_layout();
SOFTGLASS_MEASURED_LAYOUTS(SOFTGLASS_DECLARE_LAYOUT)
#undef SOFTGLASS_DECLARE_LAYOUT

const Registry<LayoutEntry>& layouts() {
#define SOFTGLASS_LIST_LAYOUT(name) name##_layout(),
  static const Registry<LayoutEntry> registry("measured-file layout",
                                              {SOFTGLASS_MEASURED_LAYOUTS(SOFTGLASS_LIST_LAYOUT)});
#undef SOFTGLASS_LIST_LAYOUT
  return registry;
}

}  // namespace measured

std::vector<RheometerCurve> read_rheometer_curves(const CsvTable& csv,
                                                  const FallbackUnits& fallback) {
  for (const measured::LayoutEntry& layout : measured::layouts().entries())
    if (layout.recognises(csv.header())) return layout.read(csv, fallback);
  throw InputError(
      fmt::format("{}: no layout of measured files recognises its header", csv.source()));
}

std::vector<MeasuredCurve> read_measured_curves(const CsvTable& csv,
                                                const FallbackUnits& fallback) {
  std::vector<MeasuredCurve> curves;
  for (RheometerCurve& c : read_rheometer_curves(csv, fallback)) {
    if (!c.has(Measured::shear_rate) || !c.has(Measured::stress)) {
      throw InputError(
          fmt::format("{}: needs a shear-rate and a stress column (e.g. 'Shear rate [1/s]', "
                      "'Stress [Pa]'); found {}",
                      csv.source(), fmt::join(csv.header(), ", ")));
    }
    MeasuredCurve& m = curves.emplace_back();
    m.label = c.label;
    m.shear_rate = std::move(c.values[Measured::shear_rate]);
    m.stress = std::move(c.values[Measured::stress]);
    if (c.has(Measured::N1)) m.N1 = std::move(c.values[Measured::N1]);
  }
  return curves;
}

std::vector<MeasuredAmplitudeSweep> read_amplitude_sweeps(const CsvTable& csv) {
  std::vector<MeasuredAmplitudeSweep> sweeps;
  for (RheometerCurve& c : read_rheometer_curves(csv, {})) {
    if (!c.has(Measured::strain_amplitude) || !c.has(Measured::storage_modulus) ||
        !c.has(Measured::loss_modulus)) {
      throw InputError(
          fmt::format("{}: an amplitude sweep needs strain-amplitude, storage- and loss-modulus "
                      "columns (e.g. 'Oscillation strain [%]', 'Storage modulus [Pa]', 'Loss "
                      "modulus [Pa]'); found {}",
                      csv.source(), fmt::join(csv.header(), ", ")));
    }
    MeasuredAmplitudeSweep& s = sweeps.emplace_back();
    s.label = c.label;
    s.strain = std::move(c.values[Measured::strain_amplitude]);
    s.storage = std::move(c.values[Measured::storage_modulus]);
    s.loss = std::move(c.values[Measured::loss_modulus]);
    if (c.has(Measured::angular_frequency)) {
      const std::vector<double>& w = c[Measured::angular_frequency];
      const auto [low, high] = std::minmax_element(w.begin(), w.end());
      if (*high > *low * (1.0 + 1e-6))
        throw InputError(fmt::format(
            "{}: curve '{}' runs from {} to {} rad/s: an amplitude sweep is at one frequency",
            csv.source(), c.label, *low, *high));
      s.angular_frequency = w.front();
    }
  }
  return sweeps;
}

}  // namespace softglass
