#include "macro/material/normal_stress.h"

#include <cmath>

namespace softglass::macro {

namespace {

class PowerLawNormalStress final : public NormalStressCurve {
 public:
  explicit PowerLawNormalStress(const NormalStressLaw& law) : law_(law) {}
  double value(double rate) const override { return law_(rate); }
  bool vanishes() const override { return law_.vanishes(); }

 private:
  NormalStressLaw law_;
};

}  // namespace

double NormalStressLaw::operator()(double rate) const {
  return yield + consistency * std::pow(rate, flow_index);
}

std::shared_ptr<const NormalStressCurve> normal_stress_curve(const NormalStressLaw& law) {
  return std::make_shared<PowerLawNormalStress>(law);
}

}  // namespace softglass::macro
