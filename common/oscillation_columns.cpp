#include "common/oscillation_columns.h"

#include <algorithm>

namespace softglass::oscillation_table {

std::string unit_of(std::string_view name) {
  const std::string_view base = name.ends_with("_se") ? name.substr(0, name.size() - 3) : name;
  for (const char* n : {phi, amplitude, frequency, packings, converged, cycles, seed})
    if (base == n && base == name) return "1";
  if (base == shear_modulus || base == flow_gradient_modulus) return "E*";
  if (std::find(responses.begin(), responses.end(), base) == responses.end()) return "";
  if (base.starts_with("intensity")) return "1";
  if (base.starts_with('v')) return "eta_s";
  return "E*";
}

}  // namespace softglass::oscillation_table
