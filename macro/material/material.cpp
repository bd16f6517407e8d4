#include "macro/material/material.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"

namespace softglass::macro {

namespace {

// "material: 'flow index' = 2.5 is not allowed; allowed: 0 < n <= 2"
void require_entry(bool condition, std::string_view entry, double value, std::string_view allowed) {
  require(condition,
          fmt::format("material: '{}' = {} is not allowed; allowed: {}", entry, value, allowed));
}

void require_finite(std::string_view entry, double value) {
  require_entry(std::isfinite(value), entry, value, "a finite number");
}

void validate_normal_stress(std::string_view name, const NormalStressLaw& law) {
  require_finite(fmt::format("{} yield", name), law.yield);
  require_finite(fmt::format("{} consistency", name), law.consistency);
  require_finite(fmt::format("{} flow index", name), law.flow_index);
  require_entry(law.flow_index > 0.0, fmt::format("{} flow index", name), law.flow_index, "> 0");
}

}  // namespace

Material herschel_bulkley_material(const std::string& model, const HerschelBulkley& law,
                                   const NormalStressLaw& n1, const NormalStressLaw& n2) {
  require_finite("yield stress", law.yield_stress);
  require_finite("consistency", law.consistency);
  require_finite("flow index", law.flow_index);
  require_entry(law.yield_stress >= 0.0, "yield stress", law.yield_stress, ">= 0 Pa");
  require_entry(law.consistency > 0.0, "consistency", law.consistency, "> 0");
  require_entry(law.flow_index > 0.0 && law.flow_index <= kLargestFlowIndex, "flow index",
                law.flow_index, fmt::format("0 < n <= {:g}", kLargestFlowIndex));
  if (model == "bingham" || model == "newtonian") {
    require_entry(law.flow_index == 1.0, "flow index", law.flow_index,
                  fmt::format("1 for model '{}'", model));
  }
  if (model == "newtonian" || model == "power-law") {
    require_entry(law.yield_stress == 0.0, "yield stress", law.yield_stress,
                  fmt::format("0 for model '{}'", model));
  }
  validate_normal_stress("N1", n1);
  validate_normal_stress("N2", n2);
  return {.model = model,
          .shear = shear_law(law),
          .first_normal_stress_difference = normal_stress_curve(n1),
          .second_normal_stress_difference = normal_stress_curve(n2)};
}

}  // namespace softglass::macro
