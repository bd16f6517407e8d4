// `power`: one power law with the user's coefficients, F(ε) = (4/3) C ε^n at
// every deformation — Hertz for C = 1, n = 3/2 — for particles whose measured
// force law is a single power (soft microgels are often fitted so).
//     F'(ε) = (4/3) C n ε^{n−1},   W(ε) = (4/3) C ε^{n+1}/(n+1).
#include <cmath>

#include "micro/contact/contact_law_impl.h"

namespace softglass::micro {
namespace {

class PowerLaw final : public ContactLawImpl<PowerLaw> {
 public:
  PowerLaw(double c, double n) : a_(4.0 / 3.0 * c), n_(n) {}

  std::string name() const override { return "power"; }

  void force_and_stiffness(double eps, double& force, double& stiffness) const {
    const double lower = std::pow(eps, n_ - 1.0);  // ε^{n−1}
    force = a_ * lower * eps;
    stiffness = a_ * n_ * lower;
  }

  double energy(double eps) const override { return a_ * std::pow(eps, n_ + 1.0) / (n_ + 1.0); }

 private:
  double a_, n_;
};

std::unique_ptr<ContactLaw> make(const ContactLawSpec& spec) {
  return std::make_unique<PowerLaw>(spec.coefficients.number("C"), spec.coefficients.number("n"));
}

}  // namespace

ContactLawEntry power_law() {
  using Kind = ComponentParameter::Kind;
  return {"power",
          "(4/3) C eps^n at every deformation (Hertz: C = 1, n = 1.5)",
          {{"C", Kind::number, "1", "Prefactor C.", 1e-6, 1e6},
           {"n", Kind::number, "1.5", "Exponent n.", 1.0, 10.0}},
          make};
}

}  // namespace softglass::micro
