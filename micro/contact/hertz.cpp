// `hertz`: the classical Hertz contact of two elastic spheres,
//     F(ε) = (4/3) ε^{3/2},   F'(ε) = 2 ε^{1/2},   W(ε) = (8/15) ε^{5/2}.
// With f = E* R_c² F(ε) and ε = h/R_c this is f = (4/3) E* R_c^{1/2} h^{3/2}.
#include <cmath>

#include "micro/contact/contact_law.h"

namespace softglass::micro {
namespace {

class HertzLaw final : public ContactLaw {
 public:
  std::string name() const override { return "hertz"; }

  void evaluate(std::span<const double> eps, std::span<double> force,
                std::span<double> stiffness) const override {
    for (std::size_t k = 0; k < eps.size(); ++k) {
      const double root = std::sqrt(eps[k]);
      force[k] = (4.0 / 3.0) * eps[k] * root;
      stiffness[k] = 2.0 * root;
    }
  }

  double energy(double eps) const override { return (8.0 / 15.0) * eps * eps * std::sqrt(eps); }
};

}  // namespace

std::unique_ptr<ContactLaw> make_hertz_law(const ContactLawSpec&) {
  return std::make_unique<HertzLaw>();
}

}  // namespace softglass::micro
