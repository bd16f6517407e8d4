// `bercovier-engelman`: the algebraic regularisation of Bercovier & Engelman
// (J. Comput. Phys. 36, 313 (1980)),
//
//     η_y(γ̇) = τ_y / √(γ̇² + ε²),    dη_y/dγ̇ = −τ_y γ̇ / (γ̇² + ε²)^{3/2},
//
// which is τ_y/γ̇ with γ̇ replaced by its smoothed magnitude √(γ̇² + ε²); it
// tends to τ_y/ε at rest and differs from τ_y/γ̇ by −τ_y ε²/(2γ̇³) + O(ε⁴).
#include <cmath>

#include "macro/material/regularised_law.h"

namespace softglass::macro {
namespace {

class BercovierEngelman final : public RegularisedLaw {
 public:
  BercovierEngelman(const ShearLaw& law, double rate_scale) : RegularisedLaw(law, rate_scale) {}

  std::string name() const override { return "bercovier-engelman"; }

 protected:
  Viscosity yield_term(double rate) const override {
    const double s = rate * rate + rate_scale() * rate_scale();
    const double value = law().yield_stress() / std::sqrt(s);
    return {.value = value, .derivative = -value * rate / s};
  }
};

std::unique_ptr<RegularisedLaw> make(const RegularisationSpec& spec) {
  return std::make_unique<BercovierEngelman>(spec.law, spec.rate_scale);
}

}  // namespace

RegularisationEntry bercovier_engelman_regularisation() {
  return {
      "bercovier-engelman", "tau_y / sqrt(rate^2 + eps^2) (Bercovier & Engelman 1980)", {}, make};
}

}  // namespace softglass::macro
