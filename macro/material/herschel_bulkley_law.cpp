// Herschel–Bulkley (herschel_bulkley.h) as the solvers' constitutive law
// (shear_law.h): Δ(γ̇) = K γ̇ⁿ, a local flow index n at every rate.
#include <fmt/format.h>

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
  std::string description() const override {
    return fmt::format("tau_y = {} Pa, K = {} Pa s^n, n = {}", law_.yield_stress,
                       law_.consistency, law_.flow_index);
  }
  double yield_stress() const override { return law_.yield_stress; }
  double stress(double rate) const override { return law_.stress(rate); }
  double excess_stress(double rate) const override {
    return law_.consistency * std::pow(rate, law_.flow_index);
  }
  double rate_at_excess(double excess) const override { return law_.rate_at_excess(excess); }
  double local_flow_index(double) const override { return law_.flow_index; }
  std::pair<double, double> flow_index_range() const override {
    return {law_.flow_index, law_.flow_index};
  }
  double viscosity(double rate) const override { return law_.viscosity(rate); }
  double rate(double stress) const override { return law_.rate(stress); }
  double proximal_rate(double trial_stress, double penalty) const override {
    return law_.proximal_rate(trial_stress, penalty);
  }

 private:
  HerschelBulkley law_;
};

}  // namespace

std::shared_ptr<const ShearLaw> shear_law(const HerschelBulkley& law) {
  return std::make_shared<HerschelBulkleyLaw>(law);
}

}  // namespace softglass::macro
