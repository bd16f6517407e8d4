// `tabulated`: the flow curve point by point (tabulated_law.h) — what
// `bridge material --tabulated` writes from the simulated σ(γ̇), N1(γ̇), N2(γ̇)
// of the particles, or what a user writes from a measured curve.
//
//     set model       = tabulated
//     set yield stress = 6.1                 # tau_y [Pa], the limit at rest
//     set rates       = 0.0043, 0.0137, …    # [1/s], increasing
//     set stresses    = 6.6, 6.9, …          # [Pa], increasing
//     set N1 values   = 0.3, 0.4, …          # optional, [Pa], one per rate
//     set N1 yield    = 0.27                 # N1 at rest [Pa]
#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include "common/errors.h"
#include "macro/material/material_model.h"
#include "macro/material/tabulated_law.h"

namespace softglass::macro {

namespace {

namespace Patterns = dealii::Patterns;

void declare(dealii::ParameterHandler& prm) {
  const auto list = Patterns::List(Patterns::Double(), 0, Patterns::List::max_int_value);
  prm.declare_entry("rates", "", list,
                    "gamma_dot_i [1/s] of a tabulated law: > 0, strictly increasing, at least 2. "
                    "Required for tabulated.",
                    true);
  prm.declare_entry("stresses", "", list,
                    "tau_i [Pa] at those rates: strictly increasing, all above the yield stress. "
                    "Required for tabulated.",
                    true);
  for (const std::string name : {"N1", "N2"})
    prm.declare_entry(name + " values", "", list,
                      name + " [Pa] at those rates (tabulated); empty: the material has no " +
                          name + ".");
}

std::vector<double> numbers(const dealii::ParameterHandler& prm, const std::string& entry) {
  std::vector<double> out;
  for (const std::string& item :
       dealii::Utilities::split_string_list(prm.get(entry), ','))
    out.push_back(dealii::Utilities::string_to_double(item));
  return out;
}

std::shared_ptr<const NormalStressCurve> normal_stress(const dealii::ParameterHandler& prm,
                                                       const FlowTable& table,
                                                       const std::string& name) {
  std::vector<double> values = numbers(prm, name + " values");
  const double rest = prm.get_double(name + " yield");
  if (values.empty()) {
    require(rest == 0.0,
            fmt::format("material (tabulated): '{} yield' = {} is set without '{} values'; "
                        "allowed: both, or neither",
                        name, rest, name));
    return normal_stress_curve(NormalStressLaw{});
  }
  return tabulated_normal_stress(table, rest, std::move(values), name);
}

std::unique_ptr<Material> make(const dealii::ParameterHandler& prm) {
  const FlowTable table{.yield_stress = prm.get_double("yield stress"),
                        .rates = numbers(prm, "rates"),
                        .stresses = numbers(prm, "stresses")};
  auto material = std::make_unique<Material>();
  material->model = "tabulated";
  material->shear = tabulated_law(table);
  material->first_normal_stress_difference = normal_stress(prm, table, "N1");
  material->second_normal_stress_difference = normal_stress(prm, table, "N2");
  return material;
}

}  // namespace

MaterialModelEntry tabulated_model() {
  return {"tabulated",
          "a flow curve point by point: monotone cubic in log-log, power laws outside",
          {},
          make,
          {declare, {"yield stress", "rates", "stresses"}}};
}

}  // namespace softglass::macro
