#include "micro/contact/contact_law.h"

#include <fmt/format.h>


#include "common/errors.h"
#include "common/input_file.h"
#include "micro/contact/registered_laws.h"

namespace softglass::micro {

#define SOFTGLASS_DECLARE_LAW(name) ContactLawEntry name##_law();
SOFTGLASS_CONTACT_LAWS(SOFTGLASS_DECLARE_LAW)
#undef SOFTGLASS_DECLARE_LAW

const Registry<ContactLawEntry>& contact_laws() {
#define SOFTGLASS_LIST_LAW(name) name##_law(),
  static const Registry<ContactLawEntry> registry("contact law",
                                                  {SOFTGLASS_CONTACT_LAWS(SOFTGLASS_LIST_LAW)});
#undef SOFTGLASS_LIST_LAW
  return registry;
}

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
  const std::string file = coefficients.has("file") ? coefficients.text("file") : "";
  if (file.empty())
    throw InputError("contact law 'table' needs 'table file' in subsection 'contact law'");
  return read_input_text(file, "contact-law table");
}

ContactLawSpec completed(const ContactLawSpec& spec) {
  const ContactLawEntry& entry = contact_laws().at(spec.name);
  ContactLawSpec out = spec;
  out.coefficients = complete_values(fmt::format("contact law '{}'", spec.name), entry.parameters,
                                     spec.coefficients);
  return out;
}

std::unique_ptr<ContactLaw> make_contact_law(const ContactLawSpec& spec) {
  return contact_laws().at(spec.name).make(completed(spec));
}

}  // namespace softglass::micro
