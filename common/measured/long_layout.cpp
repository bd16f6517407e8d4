// `long`: one row per point, columns recognised by name (columns.h), curves
// told apart by an optional label column; columns of no recognised kind
// (viscosity, time, temperature...) are ignored. Takes any header.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <map>
#include <optional>

#include "common/errors.h"
#include "common/measured/columns.h"
#include "common/measured/layout.h"

namespace softglass::measured {
namespace {

std::vector<RheometerCurve> read_long(const CsvTable& csv, const MeasuredReading& fallback) {
  std::map<Measured, Column> columns;
  std::optional<std::size_t> label;
  for (std::size_t c = 0; c < csv.columns(); ++c) {
    const ColumnName name = measured_name(csv.header()[c]);
    if (is_label(name.name)) {
      label = c;
      continue;
    }
    const Kind* kind = kind_of(name.name);
    if (!kind) continue;
    const std::string what = fmt::format("{}, column '{}'", csv.source(), csv.header()[c]);
    if (columns.contains(kind->quantity)) throw InputError(what + ": a second column of this kind");
    std::string units = name.units;
    if (units.empty()) {
      using F = Kind::Fallback;
      units = kind->fallback == F::rate     ? fallback.rate
              : kind->fallback == F::stress ? fallback.stress
                                            : std::string();
    }
    if (units.empty()) {
      throw InputError(what +
                       ": no units (write them in brackets, e.g. 'Stress [Pa]', "
                       "'Torque [mN.m]'; rates and stresses also take --rate-unit/--stress-unit)");
    }
    columns[kind->quantity] = {c, unit_factor(*kind, units, what), kind->positive};
  }
  const bool abscissa = columns.contains(Measured::shear_rate) ||
                        columns.contains(Measured::angular_velocity) ||
                        columns.contains(Measured::strain_amplitude);
  const bool ordinate = columns.contains(Measured::stress) || columns.contains(Measured::torque) ||
                        columns.contains(Measured::storage_modulus);
  if (!abscissa || !ordinate) {
    throw InputError(fmt::format(
        "{}: needs a shear-rate, angular-velocity or strain-amplitude column and a stress, "
        "torque or storage-modulus column (e.g. 'Shear rate [1/s]', 'Stress [Pa]'); found {}",
        csv.source(), fmt::join(csv.header(), ", ")));
  }
  std::vector<RheometerCurve> curves;
  std::map<std::string, std::size_t> by_label;
  const std::string file_label =
      csv.title().empty() ? std::filesystem::path(csv.source()).stem().string() : csv.title();
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const std::string name = label ? csv.text(r, *label) : file_label;
    const auto [it, fresh] = by_label.emplace(name, curves.size());
    if (fresh) curves.emplace_back().label = name;
    RheometerCurve& curve = curves[it->second];
    for (const auto& [quantity, column] : columns)
      curve.values[quantity].push_back(value(csv, r, column));
  }
  if (curves.empty()) throw InputError(csv.source() + ": no data rows");
  finish(curves, csv.source());
  return curves;
}

}  // namespace

LayoutEntry long_layout() {
  return {"long", "one row per point, columns recognised by name",
          [](const std::vector<std::string>&) { return true; }, read_long};
}

}  // namespace softglass::measured
