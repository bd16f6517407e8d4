// Herschel–Bulkley (herschel_bulkley.h) as the solvers' constitutive law
// (shear_law.h). Its viscous part K γ̇^{n−1} is unbounded at rest for n < 1
// (and vanishes there for n > 1, leaving the problem singular), so it is
// regularised with the same ε as the yield term: K (γ̇² + ε²)^{(n−1)/2},
// exactly K for n = 1.
#include <cmath>
#include <memory>

#include "macro/material/herschel_bulkley.h"
#include "macro/material/shear_law.h"

namespace softglass::macro {
namespace {

class HerschelBulkleyLaw final : public ShearLaw {
 public:
  explicit HerschelBulkleyLaw(const HerschelBulkley& law) : law_(law) {}

  std::string name() const override { return "herschel-bulkley"; }
  double yield_stress() const override { return law_.yield_stress; }
  double stress(double rate) const override { return law_.stress(rate); }
  double viscosity(double rate) const override { return law_.viscosity(rate); }
  double rate(double stress) const override { return law_.rate(stress); }
  double proximal_rate(double trial_stress, double penalty) const override {
    return law_.proximal_rate(trial_stress, penalty);
  }

  // K s^{(n−1)/2}, s = γ̇² + ε², and its γ̇-derivative K (n−1) γ̇ s^{(n−3)/2}.
  Viscosity regularised_flow_viscosity(double rate, double rate_scale) const override {
    const double n = law_.flow_index;
    const double s = rate * rate + rate_scale * rate_scale;
    const double power = law_.consistency * std::pow(s, 0.5 * (n - 1.0));
    return {.value = power, .derivative = (n - 1.0) * rate * power / s};
  }

 private:
  HerschelBulkley law_;
};

}  // namespace

std::shared_ptr<const ShearLaw> shear_law(const HerschelBulkley& law) {
  return std::make_shared<HerschelBulkleyLaw>(law);
}

}  // namespace softglass::macro
