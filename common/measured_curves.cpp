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
                                                  const MeasuredReading& fallback) {
  for (const measured::LayoutEntry& layout : measured::layouts().entries())
    if (layout.recognises(csv.header())) return layout.read(csv, fallback);
  throw InputError(
      fmt::format("{}: no layout of measured files recognises its header", csv.source()));
}

std::vector<RheometerCurve> read_rheometer_curves(const MeasuredFile& file,
                                                  const MeasuredReading& fallback) {
  std::vector<RheometerCurve> curves;
  for (const CsvTable& section : file.sections) {
    std::vector<RheometerCurve> read = read_rheometer_curves(section, fallback);
    curves.insert(curves.end(), std::make_move_iterator(read.begin()),
                  std::make_move_iterator(read.end()));
  }
  return curves;
}

namespace {

// Whether a flow curve's rates (or angular velocities) span less than 1 %: a
// step at one rate, a transient rather than a flow curve.
bool at_one_rate(const RheometerCurve& c) {
  const std::vector<double>& x =
      c.has(Measured::shear_rate) ? c[Measured::shear_rate] : c[Measured::angular_velocity];
  return x.back() < 1.01 * x.front();  // sorted by finish()
}

}  // namespace

std::vector<RheometerCurve> curves_of_kind(const MeasuredFile& file, const MeasuredReading& fallback,
                                           CurveKind kind, const std::string& advice) {
  if (file.sections.size() == 1) {
    std::vector<RheometerCurve> curves = read_rheometer_curves(file.sections[0], fallback);
    require_curve_kind(curves, kind, file.source, advice);
    return curves;
  }
  std::vector<RheometerCurve> kept;
  std::vector<std::string> left_out;
  for (const CsvTable& section : file.sections) {
    for (RheometerCurve& c : read_rheometer_curves(section, fallback)) {
      const CurveKind k = curve_kind(c);
      if (k == kind && !(k == CurveKind::flow_curve && at_one_rate(c))) {
        kept.push_back(std::move(c));
      } else {
        left_out.push_back(fmt::format("'{}' ({})", c.label,
                                       k == kind ? "a flow curve at one rate" : describe(k)));
      }
    }
  }
  if (kept.empty()) {
    throw InputError(fmt::format("'{}' ({} export) has no section that is {}; its sections: {}{}{}",
                                 file.source, file.format, describe(kind),
                                 fmt::join(left_out, ", "), advice.empty() ? "" : ": ", advice));
  }
  return kept;
}

namespace {

// The quantities of a curve, for messages: "shear rate, torque".
std::string columns_of(const RheometerCurve& c) {
  std::vector<std::string> found;
  for (const auto& [quantity, column] : c.values) found.push_back(quantity_name(quantity));
  return fmt::format("{}", fmt::join(found, ", "));
}

// A plain table as a file of one section.
MeasuredFile whole(const CsvTable& csv) {
  return {.source = csv.source(), .format = "plain", .sections = {csv}};
}

}  // namespace

std::vector<MeasuredCurve> read_measured_curves(const MeasuredFile& file,
                                                const MeasuredReading& fallback) {
  std::vector<MeasuredCurve> curves;
  for (RheometerCurve& c : curves_of_kind(file, fallback, CurveKind::flow_curve)) {
    if (!c.has(Measured::shear_rate) || !c.has(Measured::stress)) {
      throw InputError(
          fmt::format("{}: curve '{}' needs a shear-rate and a stress column (e.g. 'Shear rate "
                      "[1/s]', 'Stress [Pa]'); it has {}",
                      file.source, c.label, columns_of(c)));
    }
    MeasuredCurve& m = curves.emplace_back();
    m.label = c.label;
    m.shear_rate = std::move(c.values[Measured::shear_rate]);
    m.stress = std::move(c.values[Measured::stress]);
    if (c.has(Measured::N1)) m.N1 = std::move(c.values[Measured::N1]);
  }
  return curves;
}

std::vector<MeasuredCurve> read_measured_curves(const CsvTable& csv,
                                                const MeasuredReading& fallback) {
  return read_measured_curves(whole(csv), fallback);
}

std::vector<MeasuredAmplitudeSweep> read_amplitude_sweeps(const MeasuredFile& file) {
  std::vector<MeasuredAmplitudeSweep> sweeps;
  for (RheometerCurve& c : curves_of_kind(file, {}, CurveKind::amplitude_sweep)) {
    if (!c.has(Measured::strain_amplitude) || !c.has(Measured::storage_modulus) ||
        !c.has(Measured::loss_modulus)) {
      throw InputError(
          fmt::format("{}: curve '{}': an amplitude sweep needs strain-amplitude, storage- and "
                      "loss-modulus columns (e.g. 'Oscillation strain [%]', 'Storage modulus "
                      "[Pa]', 'Loss modulus [Pa]'); it has {}",
                      file.source, c.label, columns_of(c)));
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
            file.source, c.label, *low, *high));
      s.angular_frequency = w.front();
    }
  }
  return sweeps;
}

std::vector<MeasuredAmplitudeSweep> read_amplitude_sweeps(const CsvTable& csv) {
  return read_amplitude_sweeps(whole(csv));
}

}  // namespace softglass
