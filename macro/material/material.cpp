#include "macro/material/material.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>

#include "common/errors.h"

namespace softglass::macro {

namespace {

constexpr std::array kModelNames{"herschel-bulkley", "bingham", "power-law", "newtonian"};

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

std::string_view model_name(FlowModel model) { return kModelNames[static_cast<int>(model)]; }

FlowModel parse_flow_model(std::string_view name) {
  for (std::size_t k = 0; k < kModelNames.size(); ++k) {
    if (name == kModelNames[k]) return static_cast<FlowModel>(k);
  }
  throw InputError(fmt::format("material: model '{}' is unknown; allowed: {}", name,
                               fmt::join(kModelNames, ", ")));
}

std::vector<std::string> model_names() { return {kModelNames.begin(), kModelNames.end()}; }

double NormalStressLaw::operator()(double rate) const {
  return yield + consistency * std::pow(rate, flow_index);
}

void validate(const Material& material) {
  const HerschelBulkley& law = material.shear;
  require_finite("yield stress", law.yield_stress);
  require_finite("consistency", law.consistency);
  require_finite("flow index", law.flow_index);
  require_entry(law.yield_stress >= 0.0, "yield stress", law.yield_stress, ">= 0 Pa");
  require_entry(law.consistency > 0.0, "consistency", law.consistency, "> 0");
  require_entry(law.flow_index > 0.0 && law.flow_index <= kLargestFlowIndex, "flow index",
                law.flow_index, fmt::format("0 < n <= {:g}", kLargestFlowIndex));

  const FlowModel model = material.model;
  if (model == FlowModel::bingham || model == FlowModel::newtonian) {
    require_entry(law.flow_index == 1.0, "flow index", law.flow_index,
                  fmt::format("1 for model '{}'", model_name(model)));
  }
  if (model == FlowModel::newtonian || model == FlowModel::power_law) {
    require_entry(law.yield_stress == 0.0, "yield stress", law.yield_stress,
                  fmt::format("0 for model '{}'", model_name(model)));
  }
  validate_normal_stress("N1", material.first_normal_stress_difference);
  validate_normal_stress("N2", material.second_normal_stress_difference);
}

}  // namespace softglass::macro
