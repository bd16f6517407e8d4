#include "common/measured/columns.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

#include "common/errors.h"

namespace softglass {
namespace measured {

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
    {"rad/s", 1.0},
    {"rpm", 2.0 * std::numbers::pi / 60.0},
    {"1/min", 2.0 * std::numbers::pi / 60.0}};
const std::map<std::string, double> kForceUnits = {{"N", 1.0}, {"mN", 1e-3}, {"g", 9.80665e-3}};
const std::map<std::string, double> kStrainUnits = {{"%", 0.01}, {"1", 1.0}};
const std::map<std::string, double> kFrequencyUnits = {{"rad/s", 1.0},
                                                       {"Hz", 2.0 * std::numbers::pi}};

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
      {Measured::storage_modulus,
       {"storage modulus", "g'"},
       &kStressUnits,
       "stress",
       true,
       F::none},
      {Measured::loss_modulus, {"loss modulus", "g''"}, &kStressUnits, "stress", true, F::none},
      {Measured::strain_amplitude,
       {"oscillation strain", "strain amplitude"},
       &kStrainUnits,
       "strain",
       true,
       F::none},
      {Measured::angular_frequency,
       {"angular frequency"},
       &kFrequencyUnits,
       "frequency",
       true,
       F::none},
  };
  return k;
}

}  // namespace

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

void finish(std::vector<RheometerCurve>& curves, const std::string& source) {
  for (RheometerCurve& c : curves) {
    if (c.size() < 4) {
      throw InputError(fmt::format("{}: curve '{}' has {} point(s); at least 4 are needed", source,
                                   c.label, c.size()));
    }
    const std::vector<double>& x = c.has(Measured::shear_rate) ? c[Measured::shear_rate]
                                   : c.has(Measured::angular_velocity)
                                       ? c[Measured::angular_velocity]
                                       : c[Measured::strain_amplitude];
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

bool known_unit(const std::string& unit) {
  for (const Kind& k : kinds())
    if (k.units->contains(compact_unit(unit))) return true;
  return false;
}

double unit_factor(const Kind& kind, const std::string& unit, const std::string& what) {
  return factor(*kind.units, unit, kind.unit_kind, what);
}

}  // namespace measured

double rate_factor(const std::string& units, const std::string& what) {
  return measured::factor(measured::kRateUnits, units, "shear-rate", what);
}

double stress_factor(const std::string& units, const std::string& what) {
  return measured::factor(measured::kStressUnits, units, "stress", what);
}

}  // namespace softglass
