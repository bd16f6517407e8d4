// A material of the macro solver: its shear law and its normal stress
// differences, as read from the `subsection material` fragment
// (docs/material-format.md; reader in material_parameters.h, one material
// model per file in models/).
//
// The shear law is what the solvers and the exact references integrate
// (shear_law.h); the normal stress differences N1 = τ_xx − τ_yy and
// N2 = τ_yy − τ_zz of steady simple shear (normal_stress.h) give the normal
// forces of cone–plate and parallel-plate rheometers. Both are held through
// their interfaces, so a scene never knows which model the file chose.
#pragma once

#include <memory>
#include <string>

#include "macro/material/normal_stress.h"
#include "macro/material/shear_law.h"

namespace softglass::macro {

struct Material {
  std::string model;   ///< the file's `model`: herschel-bulkley, tabulated, …
  std::string source;  ///< the file's `source`: where it comes from (may be empty)
  std::shared_ptr<const ShearLaw> shear;
  std::shared_ptr<const NormalStressCurve> first_normal_stress_difference;   ///< N1
  std::shared_ptr<const NormalStressCurve> second_normal_stress_difference;  ///< N2
};

/// The largest flow index a material file may give (shear thickening up to
/// n = 2, docs/material-format.md).
inline constexpr double kLargestFlowIndex = 2.0;

}  // namespace softglass::macro
