// `herschel-bulkley` and its restrictions `bingham` (n = 1), `power-law`
// (τ_y = 0) and `newtonian` (both): τ = τ_y + K γ̇ⁿ above the yield stress,
// N = N_y + K_N γ̇^{n_N} for N1 and N2 (herschel_bulkley.h, normal_stress.h).
// One law, four names: a file states which restriction it means, and the
// reader holds it to it (material.h).
#include <deal.II/base/parameter_handler.h>

#include "macro/material/material_model.h"

namespace softglass::macro {

namespace {

namespace Patterns = dealii::Patterns;

void declare_normal_stress(dealii::ParameterHandler& prm, const std::string& name,
                           const std::string& difference) {
  prm.declare_entry(name + " consistency", "0", Patterns::Double(),
                    "K_N of " + difference + " = N_y + K_N gamma_dot^n_N [Pa s^n_N]; any finite "
                    "value (0: no rate dependence).");
  prm.declare_entry(name + " flow index", "1", Patterns::Double(), "n_N [1]; > 0.");
}

void declare(dealii::ParameterHandler& prm) {
  prm.declare_entry("consistency", "1", Patterns::Double(),
                    "K [Pa s^n] (the viscosity for bingham and newtonian); > 0. Required for "
                    "herschel-bulkley, bingham, power-law and newtonian.",
                    true);
  prm.declare_entry("flow index", "1", Patterns::Double(),
                    "n [1]; 0 < n <= 2, and 1 for bingham and newtonian. Required for "
                    "herschel-bulkley, bingham, power-law and newtonian.",
                    true);
  declare_normal_stress(prm, "N1", "the first normal stress difference N1");
  declare_normal_stress(prm, "N2", "the second normal stress difference N2");
}

NormalStressLaw normal_stress(const dealii::ParameterHandler& prm, const std::string& name) {
  return {.yield = prm.get_double(name + " yield"),
          .consistency = prm.get_double(name + " consistency"),
          .flow_index = prm.get_double(name + " flow index")};
}

template <const char* kName>
std::unique_ptr<Material> make(const dealii::ParameterHandler& prm) {
  const HerschelBulkley shear{.yield_stress = prm.get_double("yield stress"),
                              .consistency = prm.get_double("consistency"),
                              .flow_index = prm.get_double("flow index")};
  return std::make_unique<Material>(herschel_bulkley_material(
      kName, shear, normal_stress(prm, "N1"), normal_stress(prm, "N2")));
}

constexpr char kHerschelBulkley[] = "herschel-bulkley", kBingham[] = "bingham",
               kPowerLaw[] = "power-law", kNewtonian[] = "newtonian";

MaterialModelEntry entry(const char* name, const char* summary,
                         std::unique_ptr<Material> (*maker)(const dealii::ParameterHandler&)) {
  return {name, summary, {}, maker, {declare, {"yield stress", "consistency", "flow index"}}};
}

}  // namespace

MaterialModelEntry herschel_bulkley_model() {
  return entry(kHerschelBulkley, "tau = tau_y + K gamma_dot^n above the yield stress",
               make<kHerschelBulkley>);
}
MaterialModelEntry bingham_model() {
  return entry(kBingham, "Herschel-Bulkley with n = 1", make<kBingham>);
}
MaterialModelEntry power_law_model() {
  return entry(kPowerLaw, "Herschel-Bulkley with tau_y = 0", make<kPowerLaw>);
}
MaterialModelEntry newtonian_model() {
  return entry(kNewtonian, "Herschel-Bulkley with tau_y = 0 and n = 1", make<kNewtonian>);
}

}  // namespace softglass::macro
