// The normal stress differences of steady simple shear, N1 = τ_xx − τ_yy and
// N2 = τ_yy − τ_zz, as functions of the shear rate: what the exact references
// of the normal force (exact/cone_plate.h, exact/parallel_plates.h) and the
// scales of a scene need, and nothing of their form. The shear solvers do not
// need them: torques do not depend on them.
//
// Two forms: the power law N = N_y + K_N γ̇^{n_N} of a Herschel–Bulkley
// material file (N_y and K_N may be negative: N2 of soft glasses is), and the
// table of a simulated flow curve (tabulated_law.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace softglass::macro {

class NormalStressCurve {
 public:
  virtual ~NormalStressCurve() = default;
  /// N(γ̇) [Pa] for γ̇ ≥ 0; at γ̇ = 0 its limit from above.
  virtual double value(double rate) const = 0;
  /// Identically zero: the material file gives no such normal stress.
  virtual bool vanishes() const = 0;
  /// The rates at which N is only finitely smooth (a table's nodes), empty
  /// for an analytic law: quadratures over N split there.
  virtual std::vector<double> rate_breakpoints() const { return {}; }
};

/// N(γ̇) = N_y + K_N γ̇^{n_N} for γ̇ ≥ 0; zero when absent from the file.
struct NormalStressLaw {
  double yield = 0.0;        ///< N_y [Pa]
  double consistency = 0.0;  ///< K_N [Pa s^{n_N}]
  double flow_index = 1.0;   ///< n_N [1], > 0

  double operator()(double rate) const;
  /// N_y = K_N = 0: the material has no such normal stress difference.
  bool vanishes() const { return yield == 0.0 && consistency == 0.0; }
};

/// The power law as a NormalStressCurve.
std::shared_ptr<const NormalStressCurve> normal_stress_curve(const NormalStressLaw& law);

}  // namespace softglass::macro
