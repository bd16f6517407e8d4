#include "macro/material/slip_law.h"

#include "macro/material/slip_laws/registered_slip_laws.h"

namespace softglass::macro {

#define SOFTGLASS_DECLARE_SLIP_LAW(name) SlipLawEntry name##_slip_law();
SOFTGLASS_SLIP_LAWS(SOFTGLASS_DECLARE_SLIP_LAW)
#undef SOFTGLASS_DECLARE_SLIP_LAW

const Registry<SlipLawEntry>& slip_laws() {
#define SOFTGLASS_LIST_SLIP_LAW(name) name##_slip_law(),
  static const Registry<SlipLawEntry> registry("slip law",
                                               {SOFTGLASS_SLIP_LAWS(SOFTGLASS_LIST_SLIP_LAW)});
#undef SOFTGLASS_LIST_SLIP_LAW
  return registry;
}

std::unique_ptr<SlipLaw> make_slip_law(const std::string& name, const SlipLawSpec& spec) {
  return slip_laws().at(name).make(spec);
}

}  // namespace softglass::macro
