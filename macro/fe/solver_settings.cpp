#include "macro/fe/solver_settings.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "common/errors.h"
#include "macro/material/regularised_law.h"

namespace softglass::macro::fe {

// The presets trade cost for accuracy along the two error sources: ε/γ̇_c sets
// the regularisation error (O(ε): about ε/γ̇_c relative on flow rates and
// torques, tests/macro/fe_*), the mesh the discretisation error (Q2 elements;
// adaptive cycles concentrate cells at the yield surfaces and walls).
//   fast       ε/γ̇_c = 1e-2, no uniform refinement, 1 adaptive cycle   (~1e-2)
//   standard   ε/γ̇_c = 1e-4, 1 uniform refinement, 2 adaptive cycles   (≤ 1e-3)
//   accurate   ε/γ̇_c = 1e-5, 2 uniform refinements, 3 adaptive cycles (~1e-4)
SolverSettings preset(const std::string& name) {
  SolverSettings s;
  s.preset = name;
  if (name == "fast") {
    s.relative_rate_scale = 1e-2;
    s.global_refinements = 0;
    s.adaptive_cycles = 1;
    s.al_tolerance = 1e-4;
  } else if (name == "standard") {
    s.relative_rate_scale = 1e-4;
    s.global_refinements = 1;
    s.adaptive_cycles = 2;
    s.al_tolerance = 1e-6;
  } else if (name == "accurate") {
    s.relative_rate_scale = 1e-5;
    s.global_refinements = 2;
    s.adaptive_cycles = 3;
    s.al_tolerance = 1e-7;
  } else {
    throw InputError(fmt::format("solver: preset = '{}' is unknown; allowed: {}", name,
                                 fmt::join(preset_names(), ", ")));
  }
  return s;
}

std::vector<std::string> preset_names() {
  return {"fast", "standard", "accurate"};
}

void declare_solver_settings(dealii::ParameterHandler& prm) {
  using dealii::Patterns::Anything;
  using dealii::Patterns::Selection;
  prm.enter_subsection("solver");
  prm.declare_entry(
      "preset", "standard", Selection("fast|standard|accurate"),
      "fast | standard | accurate: regularisation, mesh and adaptive cycles together");
  prm.declare_entry("method", "regularised", Selection("regularised|augmented-lagrangian"),
                    "regularised (Newton, continuation in eps) | augmented-lagrangian (ALG2, exact "
                    "yield surfaces, slower)");
  prm.declare_entry("regularisation", "papanastasiou", Selection(regularisations().selection()),
                    "the regularised viscosity of the regularised method");
  // Overrides: empty keeps the preset's value.
  prm.declare_entry("relative rate scale", "", Anything(),
                    "eps / (the scene's shear rate) [1], > 0 and < 1; empty: the preset's");
  prm.declare_entry("degree", "", Anything(), "polynomial degree 1..4 of the elements; empty: 2");
  prm.declare_entry("global refinements", "", Anything(),
                    "uniform refinements of the scene's mesh 0..8; empty: the preset's");
  prm.declare_entry("adaptive cycles", "", Anything(),
                    "solve-estimate-refine cycles 1..10; empty: the preset's");
  prm.leave_subsection();
}

namespace {

double number(const std::string& entry, const std::string& text, double lo, double hi) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  require(used == text.size() && value >= lo && value <= hi,
          fmt::format("solver: {} = '{}' is not allowed; allowed: a number in [{}, {}]", entry,
                      text, lo, hi));
  return value;
}

}  // namespace

SolverSettings read_solver_settings(dealii::ParameterHandler& prm) {
  prm.enter_subsection("solver");
  SolverSettings s = preset(prm.get("preset"));
  s.method = prm.get("method") == "augmented-lagrangian" ? Method::augmented_lagrangian
                                                         : Method::regularised;
  s.regularisation = prm.get("regularisation");
  if (const auto t = prm.get("relative rate scale"); !t.empty()) {
    s.relative_rate_scale = number("relative rate scale", t, 1e-12, 0.5);
  }
  if (const auto t = prm.get("degree"); !t.empty()) s.fe_degree = number("degree", t, 1, 4);
  if (const auto t = prm.get("global refinements"); !t.empty())
    s.global_refinements = number("global refinements", t, 0, 8);
  if (const auto t = prm.get("adaptive cycles"); !t.empty())
    s.adaptive_cycles = number("adaptive cycles", t, 1, 10);
  prm.leave_subsection();
  return s;
}

}  // namespace softglass::macro::fe
