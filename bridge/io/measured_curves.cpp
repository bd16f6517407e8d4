#include "bridge/io/measured_curves.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <numeric>
#include <utility>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

const std::map<std::string, double> kRateUnits = {
    {"1/s", 1.0}, {"s^-1", 1.0}, {"s-1", 1.0}, {"1/min", 1.0 / 60.0}};
const std::map<std::string, double> kStressUnits = {
    {"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"mPa", 1e-3}};

std::string list_of(const std::map<std::string, double>& units) {
  std::string s;
  for (const auto& [name, factor] : units) s += (s.empty() ? "" : ", ") + name;
  return s;
}

double factor(const std::map<std::string, double>& units, const std::string& unit,
              const std::string& kind, const std::string& what) {
  std::string compact = unit;
  std::erase(compact, ' ');
  const auto it = units.find(compact);
  if (it == units.end()) {
    throw InputError(
        fmt::format("{}: '{}' is not a {} unit ({}); measured curves are in "
                    "dimensional units, all columns alike",
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

enum class Role { none, rate, stress, N1, label };

Role role_of(const std::string& name) {
  const std::string n = normalise(name);
  for (const char* r : {"shear rate", "rate", "gamma dot"})
    if (n == r) return Role::rate;
  for (const char* s : {"stress", "shear stress"})
    if (n == s) return Role::stress;
  for (const char* s : {"n1", "first normal stress difference"})
    if (n == s) return Role::N1;
  for (const char* s : {"sample", "sample id", "curve", "label"})
    if (n == s) return Role::label;
  return Role::none;
}

// "Stress [Pa]" or "stress_Pa" → {"Stress", "Pa"}; the suffix form only for known units.
ColumnName measured_name(const std::string& header) {
  ColumnName c = split_units(header);
  if (!c.units.empty()) return c;
  const auto cut = header.rfind('_');
  if (cut == std::string::npos) return c;
  const std::string suffix = header.substr(cut + 1);
  if (kRateUnits.contains(suffix) || kStressUnits.contains(suffix))
    return {header.substr(0, cut), suffix};
  return c;
}

struct Column {
  std::size_t index = 0;
  double factor = 1.0;
};

double positive(const CsvTable& csv, std::size_t row, const Column& c) {
  const double v = csv.number(row, c.index);
  if (!(v > 0)) throw InputError(fmt::format("{}: {} (must be > 0)", csv.where(row, c.index), v));
  return v * c.factor;
}

void finish(std::vector<MeasuredCurve>& curves, const std::string& source) {
  for (MeasuredCurve& c : curves) {
    if (c.shear_rate.size() < 4) {
      throw InputError(fmt::format("{}: curve '{}' has {} point(s); a fit needs at least 4", source,
                                   c.label, c.shear_rate.size()));
    }
    std::vector<std::size_t> order(c.shear_rate.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return c.shear_rate[a] < c.shear_rate[b];
    });
    const auto permute = [&](std::vector<double>& v) {
      std::vector<double> sorted;
      for (std::size_t i : order) sorted.push_back(v[i]);
      v = std::move(sorted);
    };
    permute(c.shear_rate);
    permute(c.stress);
    if (c.N1) permute(*c.N1);
  }
}

bool paired_layout(const std::vector<std::string>& header) {
  if (header.size() < 2 || header.size() % 2 != 0) return false;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c].empty() != (c % 2 == 1)) return false;
  return true;
}

std::vector<MeasuredCurve> read_paired(const CsvTable& csv, const FallbackUnits& fallback) {
  if (fallback.rate.empty() || fallback.stress.empty()) {
    throw InputError(
        fmt::format("{}: the header labels pairs of columns (shear rate, stress) but "
                    "gives no units; pass --rate-unit and --stress-unit",
                    csv.source()));
  }
  const double rate = rate_factor(fallback.rate, "--rate-unit");
  const double stress = stress_factor(fallback.stress, "--stress-unit");
  std::vector<MeasuredCurve> curves;
  for (std::size_t c = 0; c < csv.columns(); c += 2) {
    MeasuredCurve& curve = curves.emplace_back();
    curve.label = csv.header()[c];
    for (std::size_t r = 0; r < csv.rows(); ++r) {
      if (csv.text(r, c).empty() && csv.text(r, c + 1).empty()) continue;  // a shorter curve
      curve.shear_rate.push_back(positive(csv, r, {c, rate}));
      curve.stress.push_back(positive(csv, r, {c + 1, stress}));
    }
  }
  finish(curves, csv.source());
  return curves;
}

std::vector<MeasuredCurve> read_long(const CsvTable& csv, const FallbackUnits& fallback) {
  std::optional<Column> rate, stress, n1;
  std::optional<std::size_t> label;
  for (std::size_t c = 0; c < csv.columns(); ++c) {
    const ColumnName name = measured_name(csv.header()[c]);
    const Role role = role_of(name.name);
    if (role == Role::none) continue;
    const std::string what = fmt::format("{}, column '{}'", csv.source(), csv.header()[c]);
    const auto claim = [&](std::optional<Column>& slot, double f) {
      if (slot) throw InputError(what + ": a second column of this kind");
      slot = Column{c, f};
    };
    const auto units = [&](const std::string& given) {
      if (!name.units.empty()) return name.units;
      if (given.empty())
        throw InputError(what +
                         ": no units (write them in brackets, e.g. "
                         "'Stress [Pa]', or pass --rate-unit/--stress-unit)");
      return given;
    };
    switch (role) {
      case Role::rate:
        claim(rate, rate_factor(units(fallback.rate), what));
        break;
      case Role::stress:
        claim(stress, stress_factor(units(fallback.stress), what));
        break;
      case Role::N1:
        claim(n1, stress_factor(units(fallback.stress), what));
        break;
      case Role::label:
        label = c;
        break;
      case Role::none:
        break;
    }
  }
  if (!rate || !stress) {
    throw InputError(
        fmt::format("{}: needs a shear-rate and a stress column (e.g. 'Shear rate "
                    "[1/s]', 'Stress [Pa]'); found {}",
                    csv.source(), fmt::join(csv.header(), ", ")));
  }
  std::vector<MeasuredCurve> curves;
  std::map<std::string, std::size_t> by_label;
  const std::string file_label = std::filesystem::path(csv.source()).stem().string();
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const std::string name = label ? csv.text(r, *label) : file_label;
    const auto [it, fresh] = by_label.emplace(name, curves.size());
    if (fresh) {
      curves.emplace_back().label = name;
      if (n1) curves.back().N1.emplace();
    }
    MeasuredCurve& curve = curves[it->second];
    curve.shear_rate.push_back(positive(csv, r, *rate));
    curve.stress.push_back(positive(csv, r, *stress));
    if (n1) curve.N1->push_back(csv.number(r, n1->index) * n1->factor);
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

std::vector<MeasuredCurve> read_measured_curves(const CsvTable& csv,
                                                const FallbackUnits& fallback) {
  return paired_layout(csv.header()) ? read_paired(csv, fallback) : read_long(csv, fallback);
}

}  // namespace softglass::bridge
