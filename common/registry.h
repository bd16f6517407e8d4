// One way to make a pluggable component known to the tools: a registry of
// named entries, each with a one-line summary, the coefficients it takes from
// the parameter file, and its factory.
//
// A component kind (contact laws, ...) owns one Registry, built in one list
// file from one line per component; the component itself is one file that
// defines its entry. Everything else is derived from the registry: the names a
// parameter file accepts, the entries the template prints and documents
// (scripts/parameter_reference.sh turns them into docs/parameters.md), the
// defaults of unset coefficients, and the message for an unknown name.
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.h"

namespace softglass {

/// A coefficient a component takes from the parameter file.
struct ComponentParameter {
  enum class Kind {
    number,   // one real number within [lower, upper]
    numbers,  // a comma-separated list of such numbers (possibly empty)
    file,     // a file name, taken relative to the parameter file
  };
  std::string name;
  Kind kind = Kind::number;
  std::string default_value;  // as written in a parameter file
  std::string documentation;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

/// The coefficients of one component, as text by name; the typed reads parse
/// and check them and name the entry in their messages.
class ComponentValues {
 public:
  ComponentValues() = default;
  ComponentValues(std::initializer_list<std::pair<const std::string, std::string>> values)
      : values_(values) {}

  void set(const std::string& name, const std::string& value) { values_[name] = value; }
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  const std::map<std::string, std::string>& all() const { return values_; }
  bool operator==(const ComponentValues&) const = default;

  /// The text of `name`; InputError if it is not set.
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;
  std::vector<double> numbers(const std::string& name) const;

  /// "name = value" lines, the form stored in result files, and back.
  std::string serialise() const;
  static ComponentValues parse(const std::string& text);

 private:
  std::map<std::string, std::string> values_;
};

/// `values` with every declared coefficient present (unset ones take their
/// default) and checked against its kind and range; InputError names the
/// component (`what`, e.g. "contact law 'piecewise'") and the coefficient for
/// an undeclared name, an unparsable value or one out of range.
ComponentValues complete_values(const std::string& what,
                                const std::vector<ComponentParameter>& declared,
                                const ComponentValues& values);

/// No traits beyond name, summary, coefficients and factory.
struct NoTraits {};

/// A registered component: name, summary, coefficients, factory, and whatever
/// else the tools need to know of a component of this kind (`Traits`).
template <class Product, class Spec, class Traits = NoTraits>
struct ComponentEntry {
  std::string name;
  std::string summary;
  std::vector<ComponentParameter> parameters;
  std::unique_ptr<Product> (*make)(const Spec&) = nullptr;
  Traits traits{};
};

template <class Entry>
class Registry {
 public:
  /// `kind` names the component kind in messages ("contact law").
  Registry(std::string kind, std::initializer_list<Entry> entries)
      : kind_(std::move(kind)), entries_(entries) {}

  const std::string& kind() const { return kind_; }
  const std::vector<Entry>& entries() const { return entries_; }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
  }
  /// "a|b|c": the allowed values of the parameter-file entry naming one.
  std::string selection() const { return fmt::format("{}", fmt::join(names(), "|")); }

  /// The entry named `name`; InputError listing the allowed names otherwise.
  const Entry& at(const std::string& name) const {
    for (const Entry& e : entries_)
      if (e.name == name) return e;
    throw InputError(
        fmt::format("{} '{}' is unknown; allowed: {}", kind_, name, fmt::join(names(), ", ")));
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace softglass
