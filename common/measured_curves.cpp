#include "common/measured_curves.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
  throw InputError(fmt::format("{}: no layout of measured files recognises its header", csv.source()));
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

}  // namespace softglass
