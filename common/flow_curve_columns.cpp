#include "common/flow_curve_columns.h"

namespace softglass::flow_curve {

std::string unit_of(std::string_view name) {
  for (const char* n : {phi, gamma_tilde, packings, converged, coordination, seed})
    if (name == n) return "1";
  // A quantity and its parts and errors: "sigma", "sigma_elastic_se", "G0_se"...
  const auto family = [&](std::string_view base) {
    return name == base || (name.starts_with(base) && name.substr(base.size()).starts_with('_'));
  };
  for (const char* base : {shear_stress, first_normal_difference, second_normal_difference,
                           "pressure", shear_modulus})
    if (family(base)) return "E*";
  if (family(contact_force)) return "E*R^2";
  if (family(contact_distance)) return "R";
  return "";
}

}  // namespace softglass::flow_curve
