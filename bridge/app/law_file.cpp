#include "bridge/app/law_file.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <cmath>

#include <cctype>
#include <map>
#include <set>
#include <vector>

#include "common/errors.h"
#include "common/parameter_input.h"

namespace softglass::bridge {

namespace {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

// ParameterHandler names entries by mangled paths ("law.universal.k_20error":
// sections joined by '.', every character other than a letter or digit written
// as '_' and two hex digits). Turned back into what the user writes:
// "subsection law/universal: entry 'k error'".
std::string readable_entry(const std::string& mangled) {
  std::vector<std::string> parts(1);
  for (std::size_t i = 0; i < mangled.size(); ++i) {
    const char c = mangled[i];
    if (c == '.') {
      parts.emplace_back();
    } else if (c == '_' && i + 2 < mangled.size() &&
               std::isxdigit(static_cast<unsigned char>(mangled[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(mangled[i + 2]))) {
      parts.back() += static_cast<char>(std::stoi(mangled.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      parts.back() += c;
    }
  }
  const std::string entry = parts.back();
  parts.pop_back();
  std::string section;
  for (const std::string& p : parts) section += (section.empty() ? "" : "/") + p;
  return section.empty() ? fmt::format("entry '{}'", entry)
                         : fmt::format("subsection {}: entry '{}'", section, entry);
}

// Every entry is a list of numbers: one per volume fraction, or a single value.
struct Lists {
  std::map<std::string, std::vector<double>> values;

  void declare(ParameterHandler& prm, const std::string& path, const std::string& name,
               bool required) {
    prm.add_parameter(name, values[path + name], "",
                      Patterns::List(Patterns::Double(), 0, Patterns::List::max_int_value),
                      required);
  }
  const std::vector<double>& operator()(const std::string& key) const { return values.at(key); }
};

// The list `key` and its errors `key error`, `expected` values each (one per
// volume fraction, or per volume fraction and amplitude).
std::vector<Estimate> estimates(const Lists& l, const std::string& key, std::size_t expected,
                                const std::string& source) {
  const std::vector<double>& v = l(key);
  const std::vector<double>& e = l(key + " error");
  for (const auto& [list, name] : {std::pair(&v, key), std::pair(&e, key + " error")}) {
    if (list->size() != expected) {
      throw InputError(
          fmt::format("{}: '{}' has {} value(s), expected {} (one per volume fraction, or per "
                      "volume fraction and amplitude)",
                      source, name, list->size(), expected));
    }
  }
  std::vector<Estimate> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back({v[i], e[i]});
  return out;
}

// The single value `key` (no error).
double scalar_value(const Lists& l, const std::string& key, const std::string& source) {
  const std::vector<double>& v = l(key);
  if (v.size() != 1)
    throw InputError(
        fmt::format("{}: '{}' must hold one value (it holds {})", source, key, v.size()));
  return v[0];
}

// The single value `key` with its error; absent (both lists empty) only if
// not `required`: a required entry may be set, yet set to nothing.
std::optional<Estimate> scalar(const Lists& l, const std::string& key, const std::string& source,
                               bool required) {
  const std::vector<double>& v = l(key);
  const std::vector<double>& e = l(key + " error");
  if (v.empty() && e.empty() && !required) return std::nullopt;
  if (v.size() != 1 || e.size() != 1) {
    throw InputError(
        fmt::format("{}: '{}' and '{} error' must hold one value each (they hold {} and {})",
                    source, key, key, v.size(), e.size()));
  }
  return Estimate{v[0], e[0]};
}

// The optional list `key` of packing counts, one per volume fraction (empty
// when the file has none: a law written before they were recorded).
std::vector<double> packing_counts(const Lists& l, const std::string& key, std::size_t expected,
                                   const std::string& source) {
  const std::vector<double>& counts = l(key);
  if (counts.empty()) return counts;
  if (counts.size() != expected)
    throw InputError(fmt::format("{}: '{}' has {} value(s), expected {} (one per volume fraction)",
                                 source, key, counts.size(), expected));
  for (const double k : counts)
    require(k >= 1 && k == std::floor(k),
            fmt::format("{}: '{}' = {} is not a count of packings", source, key, k));
  return counts;
}

// Subsection amplitude sweep: its own volume fractions and amplitudes, the
// moduli row by row (one row of amplitudes per volume fraction).
AmplitudeSweepLaw read_amplitude_sweep(const Lists& l, const std::string& source) {
  const std::string s = "amplitude sweep/";
  AmplitudeSweepLaw a;
  a.frequency = scalar_value(l, s + "frequency", source);
  a.phi = l(s + "volume fractions");
  a.amplitudes = l(s + "amplitudes");
  const std::size_t n = a.phi.size(), m = a.amplitudes.size();
  for (auto [rows, key] : {std::pair(&a.storage, "storage"), std::pair(&a.loss, "loss")}) {
    const std::vector<Estimate> flat = estimates(l, s + key, n * m, source);
    for (std::size_t i = 0; i < n; ++i)
      rows->emplace_back(flat.begin() + static_cast<std::ptrdiff_t>(i * m),
                         flat.begin() + static_cast<std::ptrdiff_t>((i + 1) * m));
  }
  a.plateau_storage = estimates(l, s + "plateau storage", n, source);
  a.plateau_loss = estimates(l, s + "plateau loss", n, source);
  a.softening_strain = estimates(l, s + "softening strain", n, source);
  a.crossover_strain = estimates(l, s + "crossover strain", n, source);
  a.packings = packing_counts(l, s + "packings", n, source);
  for (std::size_t i = 0; i < n; ++i)
    if (a.one_packing(i)) mark_errors_unknown(a, i);
  return a;
}

}  // namespace

Law read_law_file(const std::filesystem::path& file) {
  const std::string source = file.string();
  ParameterHandler prm;
  Lists l;
  prm.enter_subsection("law");
  for (const char* name : {"volume fractions", "gamma tilde range", "shear modulus",
                           "shear modulus error", "yield strain", "yield strain error"})
    l.declare(prm, "", name, true);
  l.declare(prm, "", "packings", false);
  prm.enter_subsection("universal");
  for (const char* name : {"k", "k error", "mean exponent", "mean exponent error"})
    l.declare(prm, "universal/", name, true);
  for (const char* name : {"k N1", "k N1 error", "k N2", "k N2 error"})
    l.declare(prm, "universal/", name, false);
  prm.leave_subsection();
  for (Quantity q : kAllQuantities) {
    const std::string section = law_subsection(q);
    prm.enter_subsection(section);
    for (const char* name : {"yield", "yield error", "consistency", "consistency error", "exponent",
                             "exponent error", "correlation"})
      l.declare(prm, section + "/", name, q == Quantity::sigma);
    if (q == Quantity::force)
      for (const char* name : {"f_y", "f_y error", "k_f", "k_f error"})
        l.declare(prm, section + "/", name, false);
    prm.leave_subsection();
  }
  prm.enter_subsection("amplitude sweep");
  for (const char* name :
       {"frequency", "volume fractions", "amplitudes", "storage", "storage error", "loss",
        "loss error", "plateau storage", "plateau storage error", "plateau loss",
        "plateau loss error", "softening strain", "softening strain error", "crossover strain",
        "crossover strain error", "packings"})
    l.declare(prm, "amplitude sweep/", name, false);
  prm.leave_subsection();
  prm.leave_subsection();
  // Mandatory entries are checked below, to name them as the user writes them.
  parse_parameter_file(prm, file, "law file");
  const std::set<std::string> missing = prm.get_entries_wrongly_not_set();
  if (!missing.empty()) {
    std::string names;
    for (const std::string& m : missing) names += (names.empty() ? "" : "; ") + readable_entry(m);
    throw InputError(fmt::format("law file '{}': {} missing", source, names));
  }

  Law law;
  law.phi = l("volume fractions");
  const std::vector<double>& range = l("gamma tilde range");
  if (range.size() != 2) throw InputError(source + ": 'gamma tilde range' must hold two rates");
  law.gamma_tilde_min = range[0];
  law.gamma_tilde_max = range[1];
  law.modulus = estimates(l, "shear modulus", law.phi.size(), source);
  law.packings = packing_counts(l, "packings", law.phi.size(), source);
  for (std::size_t j = 0; j < law.packings.size(); ++j)
    if (law.packings[j] < 2) law.modulus[j].error = NAN;
  law.yield_strain = estimates(l, "yield strain", law.phi.size(), source);
  const std::pair<Quantity, const char*> constants[] = {{Quantity::sigma, "universal/k"},
                                                        {Quantity::N1, "universal/k N1"},
                                                        {Quantity::N2, "universal/k N2"}};
  for (const auto& [q, key] : constants)
    law.k[index(q)] = scalar(l, key, source, q == Quantity::sigma);
  law.mean_exponent = *scalar(l, "universal/mean exponent", source, true);
  for (Quantity q : kAllQuantities) {
    const std::string s = std::string(law_subsection(q)) + "/";
    if (l(s + "yield").empty() && q != Quantity::sigma) continue;
    HbLaw& hb = law.hb[index(q)].emplace();
    hb.yield = estimates(l, s + "yield", law.phi.size(), source);
    hb.consistency = estimates(l, s + "consistency", law.phi.size(), source);
    hb.exponent = estimates(l, s + "exponent", law.phi.size(), source);
    hb.correlation = l(s + "correlation");
  }
  const std::string force = std::string(law_subsection(Quantity::force)) + "/";
  if (!l(force + "f_y").empty() || !l(force + "k_f").empty()) {
    law.force.emplace();
    law.force->yield = estimates(l, force + "f_y", law.phi.size(), source);
    law.force->slope = estimates(l, force + "k_f", law.phi.size(), source);
  }
  if (!l("amplitude sweep/frequency").empty())
    law.amplitude_sweep = read_amplitude_sweep(l, source);
  validate(law, source);
  return law;
}

}  // namespace softglass::bridge
