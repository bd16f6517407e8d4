// `papanastasiou`: the exponential regularisation of Papanastasiou (J. Rheol.
// 31, 385 (1987)),
//
//     η_y(γ̇) = τ_y (1 − e^{−mγ̇})/γ̇ = τ_y m g(mγ̇),   g(x) = (1 − e^{−x})/x,
//
// with m = 1/ε. It equals τ_y/γ̇ up to τ_y e^{−mγ̇}/γ̇ and tends to τ_y m at rest.
// Its derivative is dη_y/dγ̇ = τ_y m² g'(mγ̇), g'(x) = ((1 + x)e^{−x} − 1)/x².
//
// Both g and g' lose digits to cancellation for small x if written as above.
// g = −expm1(−x)/x is accurate everywhere (g(0) = 1). For g' the cancellation
// of 1 against (1 + x)e^{−x} costs a factor 1/x in relative accuracy, so below
// x = 1/2 its Taylor series is summed instead,
//     g'(x) = Σ_{k≥1} (−1)^k k x^{k−1}/(k+1)!  = −1/2 + x/3 − x²/8 + …,
// whose terms fall below 1e-17 of the sum by k = 18.
#include <cmath>

#include "macro/material/regularised_law.h"

namespace softglass::macro {
namespace {

constexpr double kSeriesBelow = 0.5;
constexpr int kSeriesTerms = 18;

double g(double x) {
  return x == 0.0 ? 1.0 : -std::expm1(-x) / x;
}

double g_prime(double x) {
  if (x >= kSeriesBelow) return (std::expm1(-x) + x * std::exp(-x)) / (x * x);
  // term_k = (−1)^k k x^{k−1}/(k+1)!, built from term_{k−1} by the factor
  // −x k /((k−1)(k+1)).
  double term = -0.5, sum = term;
  for (int k = 2; k <= kSeriesTerms; ++k) {
    term *= -x * k / ((k - 1.0) * (k + 1.0));
    sum += term;
  }
  return sum;
}

class Papanastasiou final : public RegularisedLaw {
 public:
  Papanastasiou(const ShearLaw& law, double rate_scale) : RegularisedLaw(law, rate_scale) {}

  std::string name() const override { return "papanastasiou"; }

 protected:
  Viscosity yield_term(double rate) const override {
    const double m = 1.0 / rate_scale(), x = m * rate, tau_y = law().yield_stress();
    return {.value = tau_y * m * g(x), .derivative = tau_y * m * m * g_prime(x)};
  }
};

std::unique_ptr<RegularisedLaw> make(const RegularisationSpec& spec) {
  return std::make_unique<Papanastasiou>(spec.law, spec.rate_scale);
}

}  // namespace

RegularisationEntry papanastasiou_regularisation() {
  return {"papanastasiou", "tau_y (1 - exp(-rate/eps))/rate (Papanastasiou 1987)", {}, make};
}

}  // namespace softglass::macro
