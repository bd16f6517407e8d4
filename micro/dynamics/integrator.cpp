#include "micro/dynamics/integrator.h"

#include <fmt/format.h>

#include <algorithm>

#include "common/errors.h"
#include "micro/dynamics/integrators/registered_integrators.h"

namespace softglass::micro {

#define SOFTGLASS_DECLARE_INTEGRATOR(name) IntegratorEntry name##_integrator();
SOFTGLASS_INTEGRATORS(SOFTGLASS_DECLARE_INTEGRATOR)
#undef SOFTGLASS_DECLARE_INTEGRATOR

const Registry<IntegratorEntry>& integrators() {
#define SOFTGLASS_LIST_INTEGRATOR(name) name##_integrator(),
  static const Registry<IntegratorEntry> registry(
      "integrator", {SOFTGLASS_INTEGRATORS(SOFTGLASS_LIST_INTEGRATOR)});
#undef SOFTGLASS_LIST_INTEGRATOR
  return registry;
}

void Integrator::record_accepted(double dt) {
  stats_.smallest_step = stats_.accepted == 0 ? dt : std::min(stats_.smallest_step, dt);
  stats_.largest_step = std::max(stats_.largest_step, dt);
  stats_.last_step = dt;
  ++stats_.accepted;
}

void Integrator::record_rejected(Rejection cause) {
  ++stats_.rejected;
  switch (cause) {
    case Rejection::error:
      ++stats_.rejected_error;
      break;
    case Rejection::list:
      ++stats_.rejected_list;
      break;
    case Rejection::solver:
      ++stats_.rejected_solver;
      break;
  }
}

void IntegratorSpec::validate() const {
  require(tolerance >= 0.0 && tolerance <= 0.1,
          fmt::format("integrator tolerance = {} is outside [0, 0.1] (units of R; 0: the "
                      "scheme's default)",
                      tolerance));
  require(stability_fraction > 0.0 && stability_fraction < 1.0,
          fmt::format("stability fraction = {} is outside (0, 1)", stability_fraction));
  require(max_step > 0.0 && max_step <= 1.0,
          fmt::format("maximum step = {} is outside (0, 1] (strain)", max_step));
  require(solver_tolerance > 0.0 && solver_tolerance <= 1e-3,
          fmt::format("implicit solver tolerance = {} is outside (0, 1e-3]", solver_tolerance));
}

double default_tolerance(const std::string& scheme) {
  return integrators().at(scheme).traits.default_tolerance;
}

namespace {
// A tolerance of 0 stands for the named scheme's default.
IntegratorSpec with_default_tolerance(IntegratorSpec spec) {
  if (spec.tolerance == 0.0) spec.tolerance = default_tolerance(spec.name);
  return spec;
}
}  // namespace

IntegratorSpec IntegratorSpec::resolved_for(double gamma_tilde, StokesReference stokes) const {
  IntegratorSpec spec = *this;
  if (spec.name == "auto")
    spec.name =
        gamma_tilde >= kAutoImplicitBelow && stokes == StokesReference::affine ? "euler" : "bdf2";
  return with_default_tolerance(spec);
}

std::unique_ptr<Integrator> make_integrator(const IntegratorSpec& spec) {
  require(spec.name != "auto",
          "integrator 'auto' depends on the shear rate: resolve it first (resolved_for)");
  spec.validate();
  return integrators().at(spec.name).make(with_default_tolerance(spec));
}

}  // namespace softglass::micro
