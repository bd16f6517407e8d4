// `piecewise`: the paper's form F(ε) = (4/3) C ε^n with the deformation-
// dependent (n, C) taken from the parameter file — exponents on the intervals
// between breakpoints, C of the first branch, every further C from continuity.
// Its defaults are the `seth2011` reconstruction; moving the breakpoints is how
// a large-deformation law measured against another strain measure is placed
// (docs/physics.md).
#include "micro/contact/contact_law.h"
#include "micro/contact/piecewise_power_law.h"

namespace softglass::micro {
namespace {
std::unique_ptr<ContactLaw> make(const ContactLawSpec& spec) {
  const ComponentValues& c = spec.coefficients;
  return make_piecewise_contact_law(
      "piecewise", PiecewisePowerLaw::continuous("contact law 'piecewise'", c.number("C"),
                                                 c.numbers("breakpoints"), c.numbers("exponents")));
}
}  // namespace

ContactLawEntry piecewise_law() {
  using Kind = ComponentParameter::Kind;
  return {"piecewise",
          "(4/3) C eps^n with exponents n between breakpoints, C of the first branch, every "
          "further C from continuity (defaults: seth2011)",
          {{"C", Kind::number, "1", "Prefactor C of the first branch (Hertz: 1).", 1e-6, 1e6},
           {"breakpoints", Kind::numbers, "0.1, 0.2",
            "Deformations eps = h/R_c where the exponent changes, increasing.", 1e-6, 10.0},
           {"exponents", Kind::numbers, "1.5, 2, 3",
            "Exponent n of each branch, one more than breakpoints (Hertz: 1.5).", 1.0, 10.0}},
          make};
}

}  // namespace softglass::micro
