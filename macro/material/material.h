// A material of the macro solver: its shear law and its normal stress
// differences, as read from the `subsection material` fragment
// (docs/material-format.md; reader in material_parameters.h).
//
// The normal stress differences N1 = τ_xx − τ_yy and N2 = τ_yy − τ_zz of steady
// simple shear follow N = N_y + K_N γ̇^{n_N} (N_y and K_N may be negative: N2 of
// soft glasses is). The shear solvers do not need them; torques do not depend
// on them. They give the normal forces of cone–plate and parallel-plate
// rheometers (exact/cone_plate.h, exact/parallel_plates.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "macro/material/herschel_bulkley.h"

namespace softglass::macro {

/// The `model` entry: which restriction of Herschel–Bulkley the file declares.
enum class FlowModel { herschel_bulkley, bingham, power_law, newtonian };

/// The name in the material file: herschel-bulkley, bingham, power-law, newtonian.
std::string_view model_name(FlowModel model);
/// The model called `name`; InputError naming the allowed names otherwise.
FlowModel parse_flow_model(std::string_view name);
/// Every model name, in the order of the enum.
std::vector<std::string> model_names();

/// N(γ̇) = N_y + K_N γ̇^{n_N} for γ̇ ≥ 0; zero when absent from the file.
struct NormalStressLaw {
  double yield = 0.0;        ///< N_y [Pa]
  double consistency = 0.0;  ///< K_N [Pa s^{n_N}]
  double flow_index = 1.0;   ///< n_N [1], > 0

  double operator()(double rate) const;
  /// N_y = K_N = 0: the material has no such normal stress difference.
  bool vanishes() const { return yield == 0.0 && consistency == 0.0; }
};

struct Material {
  FlowModel model = FlowModel::herschel_bulkley;
  HerschelBulkley shear;
  NormalStressLaw first_normal_stress_difference;   ///< N1
  NormalStressLaw second_normal_stress_difference;  ///< N2
};

/// The largest flow index a material file may give (shear thickening up to
/// n = 2, docs/material-format.md).
inline constexpr double kLargestFlowIndex = 2.0;

/// The rules of docs/material-format.md: every value finite, yield stress ≥ 0,
/// consistency > 0, 0 < flow index ≤ 2; bingham and newtonian require flow
/// index 1, newtonian and power-law yield stress 0. One more, which the format
/// leaves implicit: N1 and N2 flow indices > 0 (a normal stress difference
/// must stay finite at rest). Throws InputError naming the entry as the file
/// spells it, its value and what is allowed.
void validate(const Material& material);

}  // namespace softglass::macro
