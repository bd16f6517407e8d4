// `hertz`: the classical Hertz contact of two elastic spheres,
//     F(ε) = (4/3) ε^{3/2},   F'(ε) = 2 ε^{1/2},   W(ε) = (8/15) ε^{5/2}.
// With f = E* R_c² F(ε) and ε = h/R_c this is f = (4/3) E* R_c^{1/2} h^{3/2}.
#include <cmath>

#include "micro/contact/contact_law_impl.h"

namespace softglass::micro {
namespace {

class HertzLaw final : public ContactLawImpl<HertzLaw> {
 public:
  std::string name() const override { return "hertz"; }

  void force_and_stiffness(double eps, double& force, double& stiffness) const {
    const double root = std::sqrt(eps);
    force = (4.0 / 3.0) * eps * root;
    stiffness = 2.0 * root;
  }

  double energy(double eps) const override { return (8.0 / 15.0) * eps * eps * std::sqrt(eps); }
};

std::unique_ptr<ContactLaw> make(const ContactLawSpec&) {
  return std::make_unique<HertzLaw>();
}

}  // namespace

ContactLawEntry hertz_law() {
  return {"hertz", "Hertz at every deformation: (4/3) eps^1.5", {}, make};
}

}  // namespace softglass::micro
