// `seth2011` (default): the paper's contact law F(ε) = (4/3) C ε^n with
// deformation-dependent (n, C), which stiffens large deformations (Liu, Williams
// & Briscoe 1998). The paper's Supplementary Fig. S2 is not available; the
// branches are those of docs/physics.md:
//
//     ε ≤ 0.1        n = 3/2   C = 1         Hertz (certain)
//     0.1 < ε ≤ 0.2  n = 2     C = √10       reconstructed (exponent: Seth et al.
//     ε > 0.2        n = 3     C = 5√10       J. Rheol. 2006; C from continuity)
//
// It is the `piecewise` law at its default coefficients, kept under its own
// name, without coefficients, as the literal reading of the paper.
#include "micro/contact/contact_law.h"
#include "micro/contact/piecewise_power_law.h"

namespace softglass::micro {

inline constexpr double kSeth2011Breakpoints[] = {0.1, 0.2};
inline constexpr double kSeth2011Exponents[] = {1.5, 2.0, 3.0};

namespace {
std::unique_ptr<ContactLaw> make(const ContactLawSpec&) {
  return make_piecewise_contact_law(
      "seth2011", PiecewisePowerLaw::continuous(
                      "contact law 'seth2011'", 1.0,
                      {std::begin(kSeth2011Breakpoints), std::end(kSeth2011Breakpoints)},
                      {std::begin(kSeth2011Exponents), std::end(kSeth2011Exponents)}));
}
}  // namespace

ContactLawEntry seth2011_law() {
  return {"seth2011",
          "the paper's law as reconstructed: Hertz up to eps = 0.1, n = 2 up to 0.2, n = 3 "
          "beyond (C from continuity)",
          {},
          make};
}

}  // namespace softglass::micro
