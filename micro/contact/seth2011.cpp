// `seth2011` (default): the paper's contact law F(ε) = (4/3) C ε^n with
// deformation-dependent (n, C), which stiffens large deformations (Liu, Williams
// & Briscoe 1998). The paper's Supplementary Fig. S2 is not available; the
// branches are those of docs/physics.md (spec model.md §3):
//
//     ε ≤ 0.1        n = 3/2   C = 1         Hertz (certain)
//     0.1 < ε ≤ 0.2  n = 2     C = √10       reconstructed (exponent: Seth et al.
//     ε > 0.2        n = 3     C = 5√10       J. Rheol. 2006; C from continuity)
//
// The C values are not typed in: each is computed here from continuity at the
// breakpoints, so changing a breakpoint or an exponent keeps the law continuous.
#include <cmath>

#include "micro/contact/contact_law_impl.h"
#include "micro/contact/piecewise_power_law.h"

namespace softglass::micro {
namespace {

struct Breakpoints {
  double hertz_end = 0.1;
  double quadratic_end = 0.2;
};

PiecewisePowerLaw seth2011_branches(const Breakpoints& bp) {
  const double a0 = 4.0 / 3.0;  // Hertz: C = 1
  // a_k ε_k^{n_k} = a_{k−1} ε_k^{n_{k−1}} at each breakpoint ε_k
  const double a1 = a0 * std::pow(bp.hertz_end, 1.5 - 2.0);
  const double a2 = a1 * std::pow(bp.quadratic_end, 2.0 - 3.0);
  return PiecewisePowerLaw({{0.0, a0, 1.5}, {bp.hertz_end, a1, 2.0}, {bp.quadratic_end, a2, 3.0}});
}

class Seth2011Law final : public ContactLawImpl<Seth2011Law> {
 public:
  Seth2011Law() : law_(seth2011_branches(Breakpoints{})) {}

  std::string name() const override { return "seth2011"; }

  void force_and_stiffness(double eps, double& force, double& stiffness) const {
    law_.evaluate(eps, force, stiffness);
  }

  double energy(double eps) const override { return law_.energy(eps); }

 private:
  PiecewisePowerLaw law_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_seth2011_law(const ContactLawSpec&) {
  return std::make_unique<Seth2011Law>();
}

}  // namespace softglass::micro
