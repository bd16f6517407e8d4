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

const std::vector<double>& RheometerCurve::operator[](Measured q) const {
  const auto it = values.find(q);
  if (it == values.end())
    throw InputError(fmt::format("curve '{}' has no {} column", label, quantity_name(q)));
  return it->second;
}

std::string quantity_name(Measured q) {
  switch (q) {
    case Measured::shear_rate:
      return "shear rate";
    case Measured::stress:
      return "stress";
    case Measured::N1:
      return "N1";
    case Measured::torque:
      return "torque";
    case Measured::angular_velocity:
      return "angular velocity";
    case Measured::normal_force:
      return "normal force";
    case Measured::storage_modulus:
      return "G′";
    case Measured::loss_modulus:
      return "G″";
    case Measured::strain_amplitude:
      return "strain amplitude";
    case Measured::angular_frequency:
      return "angular frequency";
  }
  return "unknown quantity";
}

CurveKind curve_kind(const RheometerCurve& c) {
  // An oscillation export may carry a rate or a torque column as well (the
  // oscillation's strain rate, its torque amplitude): its strain amplitude
  // and moduli decide.
  if (c.has(Measured::strain_amplitude) &&
      (c.has(Measured::storage_modulus) || c.has(Measured::loss_modulus)))
    return CurveKind::amplitude_sweep;
  if ((c.has(Measured::shear_rate) || c.has(Measured::angular_velocity)) &&
      (c.has(Measured::stress) || c.has(Measured::torque)))
    return CurveKind::flow_curve;
  return CurveKind::other;
}

std::string describe(CurveKind kind) {
  switch (kind) {
    case CurveKind::flow_curve:
      return "a flow curve (shear rate or angular velocity, and stress or torque columns)";
    case CurveKind::amplitude_sweep:
      return "an amplitude sweep (strain amplitude and G′/G″ columns)";
    case CurveKind::other:
      break;
  }
  return "neither a flow curve nor an amplitude sweep";
}

void require_curve_kind(const std::vector<RheometerCurve>& curves, CurveKind expected,
                        const std::string& source, const std::string& advice) {
  for (const RheometerCurve& c : curves) {
    const CurveKind kind = curve_kind(c);
    if (kind == expected) continue;
    std::vector<std::string> found;
    for (const auto& [quantity, column] : c.values) found.push_back(quantity_name(quantity));
    throw InputError(fmt::format(
        "'{}' is {}, not {}{}{}", source,
        kind == CurveKind::other
            ? fmt::format("{} (its columns: {})", describe(kind), fmt::join(found, ", "))
            : describe(kind),
        describe(expected), advice.empty() ? "" : ": ", advice));
  }
}

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
  std::vector<RheometerCurve> read = read_rheometer_curves(csv, fallback);
  require_curve_kind(read, CurveKind::flow_curve, csv.source());
  for (RheometerCurve& c : read) {
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
  std::vector<RheometerCurve> read = read_rheometer_curves(csv, {});
  require_curve_kind(read, CurveKind::amplitude_sweep, csv.source());
  for (RheometerCurve& c : read) {
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
