#include "macro/material/slip_parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include "common/deal_ii_message.h"
#include "common/errors.h"

namespace softglass::macro {

namespace Patterns = dealii::Patterns;

void declare_slip_law(dealii::ParameterHandler& prm) {
  std::string laws = "the wall stress sigma_w against the slip velocity V_s of the walls a "
                     "scene's 'slip walls' names:";
  for (const SlipLawEntry& e : slip_laws().entries()) laws += " " + e.name + ": " + e.summary + ";";
  laws.back() = '.';
  prm.enter_subsection("slip");
  prm.declare_entry("law", slip_laws().names().front(), Patterns::Selection(slip_laws().selection()),
                    laws);
  prm.declare_entry("coefficient", "0", Patterns::Double(),
                    "beta [m/s/Pa^p], > 0; required with slip walls");
  prm.declare_entry("exponent", "0", Patterns::Double(),
                    "p [1], > 0 (2: the fixed-load EHD estimate; 1: Navier slip); required with "
                    "slip walls");
  prm.declare_entry("yield stress", "0", Patterns::Double(),
                    "sigma_s [Pa], >= 0: no slip below it");
  prm.leave_subsection();
}

std::shared_ptr<const SlipLaw> read_slip_law(dealii::ParameterHandler& prm) {
  prm.enter_subsection("slip");
  SlipLawSpec spec;
  std::string law;
  try {
    law = prm.get("law");
    spec = {.coefficient = prm.get_double("coefficient"),
            .exponent = prm.get_double("exponent"),
            .yield_stress = prm.get_double("yield stress")};
  } catch (const dealii::ExceptionBase& error) {
    // A value the pattern accepts but the conversion cannot represent (1e-400).
    prm.leave_subsection();
    throw InputError(fmt::format("slip: {}", deal_ii_message(error.what())));
  }
  prm.leave_subsection();
  return make_slip_law(law, spec);
}

}  // namespace softglass::macro
