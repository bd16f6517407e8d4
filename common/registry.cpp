#include "common/registry.h"

#include <cmath>
#include <sstream>

namespace softglass {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

// A whole-string real number, or false.
bool parse_real(const std::string& text, double& value) {
  const std::string t = trimmed(text);
  if (t.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stod(t, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == t.size();
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  if (trimmed(text).empty()) return items;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) items.push_back(trimmed(item));
  return items;
}

}  // namespace

const std::string& ComponentValues::text(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw InputError(fmt::format("coefficient '{}' is not set", name));
  return it->second;
}

double ComponentValues::number(const std::string& name) const {
  double value = 0.0;
  if (!parse_real(text(name), value))
    throw InputError(fmt::format("coefficient '{}' = '{}' is not a number", name, text(name)));
  return value;
}

std::vector<double> ComponentValues::numbers(const std::string& name) const {
  std::vector<double> out;
  for (const std::string& item : split_list(text(name))) {
    double value = 0.0;
    if (!parse_real(item, value))
      throw InputError(fmt::format("coefficient '{}': '{}' is not a number", name, item));
    out.push_back(value);
  }
  return out;
}

std::string ComponentValues::serialise() const {
  std::string out;
  for (const auto& [name, value] : values_) out += name + " = " + value + "\n";
  return out;
}

ComponentValues ComponentValues::parse(const std::string& text) {
  ComponentValues values;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) {
      if (!trimmed(line).empty())
        throw InputError(
            fmt::format("component coefficients: line '{}' is not 'name = value'", line));
      continue;
    }
    values.set(trimmed(line.substr(0, eq)), trimmed(line.substr(eq + 3)));
  }
  return values;
}

ComponentValues complete_values(const std::string& what,
                                const std::vector<ComponentParameter>& declared,
                                const ComponentValues& values) {
  for (const auto& [name, value] : values.all()) {
    bool known = false;
    for (const ComponentParameter& p : declared) known = known || p.name == name;
    if (!known) throw InputError(fmt::format("{} has no coefficient '{}'", what, name));
  }
  ComponentValues out;
  for (const ComponentParameter& p : declared) {
    out.set(p.name, values.has(p.name) ? values.text(p.name) : p.default_value);
    if (p.kind == ComponentParameter::Kind::file) continue;
    std::vector<double> numbers;
    try {
      numbers = p.kind == ComponentParameter::Kind::number ? std::vector<double>{out.number(p.name)}
                                                           : out.numbers(p.name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", what, e.what()));
    }
    for (double x : numbers) {
      if (!std::isfinite(x) || x < p.lower || x > p.upper)
        throw InputError(fmt::format("{}: coefficient '{}' = {} is outside [{:g}, {:g}]", what,
                                     p.name, x, p.lower, p.upper));
    }
  }
  return out;
}

}  // namespace softglass
