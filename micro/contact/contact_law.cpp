#include "micro/contact/contact_law.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <fstream>
#include <functional>
#include <iterator>

#include "common/errors.h"

namespace softglass::micro {

// Each law lives in its own file and provides its factory.
std::unique_ptr<ContactLaw> make_hertz_law(const ContactLawSpec&);
std::unique_ptr<ContactLaw> make_seth2011_law(const ContactLawSpec&);
std::unique_ptr<ContactLaw> make_table_law(const ContactLawSpec&);

namespace {
struct RegisteredLaw {
  const char* name;
  std::unique_ptr<ContactLaw> (*make)(const ContactLawSpec&);
};
constexpr std::array kRegistry{
    RegisteredLaw{"seth2011", make_seth2011_law},
    RegisteredLaw{"hertz", make_hertz_law},
    RegisteredLaw{"table", make_table_law},
};
}  // namespace

double ContactLaw::force(double deformation) const {
  double f = 0.0, k = 0.0;
  evaluate({&deformation, 1}, {&f, 1}, {&k, 1});
  return f;
}

double ContactLaw::stiffness(double deformation) const {
  double f = 0.0, k = 0.0;
  evaluate({&deformation, 1}, {&f, 1}, {&k, 1});
  return k;
}

std::string ContactLawSpec::table() const {
  if (name != "table" || !table_text.empty()) return table_text;
  std::ifstream in(table_file);
  if (!in) throw InputError(fmt::format("contact-law table '{}' cannot be opened", table_file.string()));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> contact_law_names() {
  std::vector<std::string> names;
  for (const auto& law : kRegistry) names.emplace_back(law.name);
  return names;
}

std::unique_ptr<ContactLaw> make_contact_law(const ContactLawSpec& spec) {
  for (const auto& law : kRegistry) {
    if (spec.name == law.name) return law.make(spec);
  }
  throw InputError(fmt::format("contact law '{}' is unknown; allowed: {}", spec.name,
                               fmt::join(contact_law_names(), ", ")));
}

}  // namespace softglass::micro
