#include "common/measured_curves.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <utility>

#include "common/errors.h"

namespace softglass {

namespace {

const std::map<std::string, double> kRateUnits = {
    {"1/s", 1.0}, {"s^-1", 1.0}, {"s-1", 1.0}, {"1/min", 1.0 / 60.0}};
const std::map<std::string, double> kStressUnits = {
    {"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"mPa", 1e-3}};
// Written after spaces are dropped and "·", "*" and "Nm" are read as "N.m";
// the micro sign may come as µ (U+00B5), μ (U+03BC) or u.
const std::map<std::string, double> kTorqueUnits = {{"N.m", 1.0},   {"mN.m", 1e-3}, {"µN.m", 1e-6},
                                                    {"μN.m", 1e-6}, {"uN.m", 1e-6}, {"nN.m", 1e-9}};
const std::map<std::string, double> kAngularVelocityUnits = {
    {"rad/s", 1.0}, {"rpm", 2.0 * std::numbers::pi / 60.0}};
const std::map<std::string, double> kForceUnits = {{"N", 1.0}, {"mN", 1e-3}, {"g", 9.80665e-3}};

std::string list_of(const std::map<std::string, double>& units) {
  std::string s;
  for (const auto& [name, factor] : units) s += (s.empty() ? "" : ", ") + name;
  return s;
}

std::string replace_all(const std::string& s, const std::string& from, const std::string& to) {
  std::string out;
  std::size_t start = 0;
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, start)) {
    out.append(s, start, at - start).append(to);
    start = at + from.size();
  }
  return out.append(s, start, std::string::npos);
}

// "µN m", "µN·m", "µNm" → "µN.m"; other units lose their spaces only.
std::string compact_unit(const std::string& unit) {
  std::string c = unit;
  std::erase(c, ' ');
  c = replace_all(replace_all(c, "·", "."), "*", ".");
  if (c.ends_with("Nm")) c = c.substr(0, c.size() - 1) + ".m";
  return c;
}

double factor(const std::map<std::string, double>& units, const std::string& unit,
              const std::string& kind, const std::string& what) {
  const auto it = units.find(compact_unit(unit));
  if (it == units.end()) {
    throw InputError(
        fmt::format("{}: '{}' is not a {} unit ({}); measured data are in "
                    "dimensional units",
                    what, unit, kind, list_of(units)));
  }
  return it->second;
}

// Lower case, '_' and '-' as spaces, single spaces.
std::string normalise(const std::string& name) {
  std::string out;
  for (char c : name) {
    const char d = (c == '_' || c == '-')
                       ? ' '
                       : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (d == ' ' && (out.empty() || out.back() == ' ')) continue;
    out += d;
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// What a recognised column holds: its names, its units, whether it must be
// positive and whether the command line's fallback units apply.
struct Kind {
  Measured quantity;
  std::vector<std::string> names;
  const std::map<std::string, double>* units;
  const char* unit_kind;
  bool positive;
  enum class Fallback { none, rate, stress } fallback;
};

const std::vector<Kind>& kinds() {
  using F = Kind::Fallback;
  static const std::vector<Kind> k = {
      {Measured::shear_rate,
       {"shear rate", "rate", "gamma dot"},
       &kRateUnits,
       "shear-rate",
       true,
       F::rate},
      {Measured::stress, {"stress", "shear stress"}, &kStressUnits, "stress", true, F::stress},
      {Measured::N1,
       {"n1", "first normal stress difference"},
       &kStressUnits,
       "stress",
       false,
       F::stress},
      {Measured::torque, {"torque"}, &kTorqueUnits, "torque", true, F::none},
      {Measured::angular_velocity,
       {"angular velocity", "rotation rate", "angular speed", "omega"},
       &kAngularVelocityUnits,
       "angular-velocity",
       true,
       F::none},
      {Measured::normal_force,
       {"normal force", "axial force"},
       &kForceUnits,
       "force",
       false,
       F::none},
  };
  return k;
}

const Kind* kind_of(const std::string& name) {
  const std::string n = normalise(name);
  for (const Kind& k : kinds())
    if (std::find(k.names.begin(), k.names.end(), n) != k.names.end()) return &k;
  return nullptr;
}

bool is_label(const std::string& name) {
  const std::string n = normalise(name);
  for (const char* s : {"sample", "sample id", "curve", "label"})
    if (n == s) return true;
  return false;
}

// "Stress [Pa]" or "stress_Pa" → {"Stress", "Pa"}; the suffix form only for known units.
ColumnName measured_name(const std::string& header) {
  ColumnName c = split_units(header);
  if (!c.units.empty()) return c;
  const auto cut = header.rfind('_');
  if (cut == std::string::npos) return c;
  const std::string suffix = header.substr(cut + 1);
  for (const Kind& k : kinds())
    if (k.units->contains(compact_unit(suffix))) return {header.substr(0, cut), suffix};
  return c;
}

struct Column {
  std::size_t index = 0;
  double factor = 1.0;
  bool positive = true;
};

double value(const CsvTable& csv, std::size_t row, const Column& c) {
  const double v = csv.number(row, c.index);
  if (c.positive && !(v > 0))
    throw InputError(fmt::format("{}: {} (must be > 0)", csv.where(row, c.index), v));
  // Converted to SI units, a value near the ends of the double range would
  // overflow to inf or underflow to 0 (1e308 kPa, 1e-320 1/min); measured
  // data lie far inside these bounds.
  const double si = v * c.factor;
  if (v != 0 && !(std::abs(si) >= 1e-300 && std::abs(si) <= 1e300)) {
    throw InputError(
        fmt::format("{}: {} is {} in SI units (x {}); allowed: 1e-300 <= |value| <= "
                    "1e300 in SI units",
                    csv.where(row, c.index), v, si, c.factor));
  }
  return si;
}

// Sorts every column of each curve by the abscissa; at least 4 points each.
void finish(std::vector<RheometerCurve>& curves, const std::string& source) {
  for (RheometerCurve& c : curves) {
    if (c.size() < 4) {
      throw InputError(fmt::format("{}: curve '{}' has {} point(s); at least 4 are needed", source,
                                   c.label, c.size()));
    }
    const std::vector<double>& x =
        c.has(Measured::shear_rate) ? c[Measured::shear_rate] : c[Measured::angular_velocity];
    std::vector<std::size_t> order(x.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    for (auto& [quantity, v] : c.values) {
      std::vector<double> sorted;
      for (std::size_t i : order) sorted.push_back(v[i]);
      v = std::move(sorted);
    }
  }
}

bool paired_layout(const std::vector<std::string>& header) {
  if (header.size() < 2 || header.size() % 2 != 0) return false;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c].empty() != (c % 2 == 1)) return false;
  return true;
}

std::vector<RheometerCurve> read_paired(const CsvTable& csv, const FallbackUnits& fallback) {
  if (fallback.rate.empty() || fallback.stress.empty()) {
    throw InputError(
        fmt::format("{}: the header labels pairs of columns (shear rate, stress) but "
                    "gives no units; pass --rate-unit and --stress-unit",
                    csv.source()));
  }
  const double rate = rate_factor(fallback.rate, "--rate-unit");
  const double stress = stress_factor(fallback.stress, "--stress-unit");
  std::vector<RheometerCurve> curves;
  for (std::size_t c = 0; c < csv.columns(); c += 2) {
    RheometerCurve& curve = curves.emplace_back();
    curve.label = csv.header()[c];
    std::vector<double>& x = curve.values[Measured::shear_rate];
    std::vector<double>& y = curve.values[Measured::stress];
    for (std::size_t r = 0; r < csv.rows(); ++r) {
      if (csv.text(r, c).empty() && csv.text(r, c + 1).empty()) continue;  // a shorter curve
      x.push_back(value(csv, r, {c, rate}));
      y.push_back(value(csv, r, {c + 1, stress}));
    }
  }
  finish(curves, csv.source());
  return curves;
}

std::vector<RheometerCurve> read_long(const CsvTable& csv, const FallbackUnits& fallback) {
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
    columns[kind->quantity] = {c, factor(*kind->units, units, kind->unit_kind, what),
                               kind->positive};
  }
  const bool abscissa =
      columns.contains(Measured::shear_rate) || columns.contains(Measured::angular_velocity);
  const bool ordinate = columns.contains(Measured::stress) || columns.contains(Measured::torque);
  if (!abscissa || !ordinate) {
    throw InputError(
        fmt::format("{}: needs a shear-rate or angular-velocity column and a stress or torque "
                    "column (e.g. 'Shear rate [1/s]', 'Stress [Pa]'); found {}",
                    csv.source(), fmt::join(csv.header(), ", ")));
  }
  std::vector<RheometerCurve> curves;
  std::map<std::string, std::size_t> by_label;
  const std::string file_label = std::filesystem::path(csv.source()).stem().string();
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

double rate_factor(const std::string& units, const std::string& what) {
  return factor(kRateUnits, units, "shear-rate", what);
}

double stress_factor(const std::string& units, const std::string& what) {
  return factor(kStressUnits, units, "stress", what);
}

std::vector<RheometerCurve> read_rheometer_curves(const CsvTable& csv,
                                                  const FallbackUnits& fallback) {
  return paired_layout(csv.header()) ? read_paired(csv, fallback) : read_long(csv, fallback);
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
