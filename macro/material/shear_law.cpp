#include "macro/material/shear_law.h"

#include <cmath>

namespace softglass::macro {

Viscosity ShearLaw::regularised_flow_viscosity(double rate, double rate_scale) const {
  const double s = std::hypot(rate, rate_scale);
  const auto [excess, n] = excess_and_flow_index(s);
  return {.value = excess / s, .derivative = (n - 1.0) * excess * rate / (s * s * s)};
}

}  // namespace softglass::macro
