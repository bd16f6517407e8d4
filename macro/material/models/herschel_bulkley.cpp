// `herschel-bulkley` and its restrictions `bingham` (n = 1), `power-law`
// (τ_y = 0) and `newtonian` (both): τ = τ_y + K γ̇ⁿ above the yield stress,
// N = N_y + K_N γ̇^{n_N} for N1 and N2 (herschel_bulkley.h, normal_stress.h).
// One law, four names: a file states which restriction it means, and the
// reader holds it to it.
//
// The rules (docs/material-format.md): every value finite, yield stress ≥ 0,
// consistency > 0, 0 < flow index ≤ 2; a restriction's fixed values exactly;
// N1 and N2 flow indices > 0 (a normal stress difference must stay finite at
// rest). A violation is an InputError naming the entry as the file spells it,
// its value and what is allowed.
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"
#include "macro/material/herschel_bulkley.h"
#include "macro/material/material_model.h"

namespace softglass::macro {

namespace {

namespace Patterns = dealii::Patterns;

// What a model of the family fixes.
struct Restriction {
  const char* name;
  const char* summary;
  bool unit_flow_index;  // n = 1
  bool no_yield_stress;  // τ_y = 0
};

constexpr Restriction kHerschelBulkley{
    "herschel-bulkley", "tau = tau_y + K gamma_dot^n above the yield stress", false, false};
constexpr Restriction kBingham{"bingham", "Herschel-Bulkley with n = 1", true, false};
constexpr Restriction kPowerLaw{"power-law", "Herschel-Bulkley with tau_y = 0", false, true};
constexpr Restriction kNewtonian{"newtonian", "Herschel-Bulkley with tau_y = 0 and n = 1", true,
                                 true};

// "material: 'flow index' = 2.5 is not allowed; allowed: 0 < n <= 2"
void require_entry(bool condition, std::string_view entry, double value, std::string_view allowed) {
  require(condition,
          fmt::format("material: '{}' = {} is not allowed; allowed: {}", entry, value, allowed));
}

void require_finite(std::string_view entry, double value) {
  require_entry(std::isfinite(value), entry, value, "a finite number");
}

void validate(const Restriction& r, const HerschelBulkley& law) {
  require_finite("yield stress", law.yield_stress);
  require_finite("consistency", law.consistency);
  require_finite("flow index", law.flow_index);
  require_entry(law.yield_stress >= 0.0, "yield stress", law.yield_stress, ">= 0 Pa");
  require_entry(law.consistency > 0.0, "consistency", law.consistency, "> 0");
  require_entry(law.flow_index > 0.0 && law.flow_index <= kLargestFlowIndex, "flow index",
                law.flow_index, fmt::format("0 < n <= {:g}", kLargestFlowIndex));
  if (r.unit_flow_index)
    require_entry(law.flow_index == 1.0, "flow index", law.flow_index,
                  fmt::format("1 for model '{}'", r.name));
  if (r.no_yield_stress)
    require_entry(law.yield_stress == 0.0, "yield stress", law.yield_stress,
                  fmt::format("0 for model '{}'", r.name));
}

void validate_normal_stress(std::string_view name, const NormalStressLaw& law) {
  require_finite(fmt::format("{} yield", name), law.yield);
  require_finite(fmt::format("{} consistency", name), law.consistency);
  require_finite(fmt::format("{} flow index", name), law.flow_index);
  require_entry(law.flow_index > 0.0, fmt::format("{} flow index", name), law.flow_index, "> 0");
}

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
  const NormalStressLaw law{.yield = prm.get_double(name + " yield"),
                            .consistency = prm.get_double(name + " consistency"),
                            .flow_index = prm.get_double(name + " flow index")};
  validate_normal_stress(name, law);
  return law;
}

template <const Restriction& kRestriction>
std::unique_ptr<Material> make(const dealii::ParameterHandler& prm) {
  const HerschelBulkley shear{.yield_stress = prm.get_double("yield stress"),
                              .consistency = prm.get_double("consistency"),
                              .flow_index = prm.get_double("flow index")};
  validate(kRestriction, shear);
  return std::make_unique<Material>(Material{
      .model = kRestriction.name,
      .source = {},
      .shear = shear_law(shear),
      .first_normal_stress_difference = normal_stress_curve(normal_stress(prm, "N1")),
      .second_normal_stress_difference = normal_stress_curve(normal_stress(prm, "N2"))});
}

template <const Restriction& kRestriction>
MaterialModelEntry entry() {
  return {kRestriction.name,
          kRestriction.summary,
          {},
          make<kRestriction>,
          {declare, {"yield stress", "consistency", "flow index"}}};
}

}  // namespace

MaterialModelEntry herschel_bulkley_model() { return entry<kHerschelBulkley>(); }
MaterialModelEntry bingham_model() { return entry<kBingham>(); }
MaterialModelEntry power_law_model() { return entry<kPowerLaw>(); }
MaterialModelEntry newtonian_model() { return entry<kNewtonian>(); }

}  // namespace softglass::macro
