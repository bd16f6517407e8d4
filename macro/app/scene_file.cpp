#include "macro/app/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/parameter_input.h"
#include "common/errors.h"
#include "macro/fe/solver_settings.h"
#include "macro/material/material_parameters.h"
#include "macro/material/slip_parameters.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::app {

namespace Patterns = dealii::Patterns;

void declare_scene_file(dealii::ParameterHandler& prm) {
  declare_scenes(prm);
  declare_material(prm);
  declare_slip_law(prm);
  fe::declare_solver_settings(prm);
  prm.enter_subsection("sweep");
  prm.declare_entry("values", "", Patterns::List(Patterns::Double(), 0, 100000),
                    "operating points: rotation rates [rad/s] or pressure gradients [Pa/m], > 0, "
                    "comma-separated; empty: first/last/points/spacing");
  prm.declare_entry("first", "1", Patterns::Double(), "first operating point (> 0)");
  prm.declare_entry("last", "1", Patterns::Double(), "last operating point (> 0)");
  prm.declare_entry("points", "1", Patterns::Integer(1, 100000), "number of operating points");
  prm.declare_entry("spacing", "log", Patterns::Selection("log|linear"), "log | linear");
  prm.leave_subsection();
  prm.enter_subsection("output");
  prm.declare_entry("vtu", "last", Patterns::Selection("none|last|all"),
                    "ParaView fields: none | last (operating point) | all");
  prm.leave_subsection();
}

std::vector<SetEntry> parse_scene_file(dealii::ParameterHandler& prm,
                                       const std::filesystem::path& file) {
  const std::vector<SetEntry> entries = parse_parameter_file(prm, file, "scene file");
  const std::string chosen = prm.get("scene");
  const std::vector<std::string> names = scenes().names();
  for (const SetEntry& e : entries) {
    if (e.subsections.empty() || e.subsections.front() == chosen ||
        std::find(names.begin(), names.end(), e.subsections.front()) == names.end())
      continue;
    throw InputError(fmt::format(
        "scene file '{}', line {} of file '{}': '{}/{}' is set, but the scene is '{}'{}; set "
        "scene = {} to use it, or remove the subsection",
        file.string(), e.line, e.file, e.subsections.front(), e.name, chosen,
        std::any_of(entries.begin(), entries.end(),
                    [](const SetEntry& s) { return s.subsections.empty() && s.name == "scene"; })
            ? ""
            : " (the default: the file does not set scene)",
        e.subsections.front()));
  }
  return entries;
}

namespace {

// The scene's material, or the fragment file `override` when it is not empty:
// `prm` then states it instead (for the summary's parameter listing), and its
// entries replace the scene file's material entries in `entries`.
Material read_scene_material(dealii::ParameterHandler& prm, const std::filesystem::path& override,
                             std::vector<SetEntry>& entries) {
  if (override.empty()) return read_material(prm);
  MaterialFile fragment = read_material_file(override);
  set_material(prm, fragment.entries);
  std::erase_if(entries, [](const SetEntry& e) {
    return !e.subsections.empty() && e.subsections.front() == "material";
  });
  entries.insert(entries.end(), fragment.entries.begin(), fragment.entries.end());
  return fragment.material;
}

// Sets `solver/preset` unless `preset` is empty (the command line's --preset).
void override_preset(dealii::ParameterHandler& prm, const std::string& preset) {
  if (preset.empty()) return;
  prm.enter_subsection("solver");
  try {
    prm.set("preset", preset);
  } catch (const dealii::ExceptionBase&) {
    throw InputError(
        fmt::format("--preset {} is unknown; allowed: fast, standard, accurate", preset));
  }
  prm.leave_subsection();
}

}  // namespace

SceneInput read_scene_input(dealii::ParameterHandler& prm, const std::filesystem::path& file,
                            const std::string& preset, const std::filesystem::path& material) {
  declare_scene_file(prm);
  std::vector<SetEntry> entries = in_effect(parse_scene_file(prm, file));
  override_preset(prm, preset);
  Material scene_material = read_scene_material(prm, material, entries);
  return {.material = std::move(scene_material),
          .settings = fe::read_solver_settings(prm),
          .entries = std::move(entries)};
}

std::vector<double> read_sweep(dealii::ParameterHandler& prm) {
  prm.enter_subsection("sweep");
  // Every operating point finite and > 0 (text such as 1e-320 or 1e999 that
  // deal.II cannot convert is refused alike).
  const auto number = [](const std::string& text, const std::string& what) {
    double v = NAN;
    try {
      v = dealii::Utilities::string_to_double(text);
    } catch (const dealii::ExceptionBase&) {
    }
    require(std::isfinite(v) && v > 0.0,
            fmt::format("sweep: {} {}, which is not allowed; allowed: a finite number > 0", what,
                        text));
    return v;
  };
  std::vector<double> points;
  const std::string values = prm.get("values");
  if (!values.empty()) {
    for (const std::string& item : dealii::Utilities::split_string_list(values))
      points.push_back(number(item, "values holds"));
  } else {
    const double first = number(prm.get("first"), "first ="),
                 last = number(prm.get("last"), "last =");
    const int n = prm.get_integer("points");
    const bool log = prm.get("spacing") == "log";
    for (int k = 0; k < n; ++k) {
      const double t = n == 1 ? 0.0 : double(k) / (n - 1);
      // Logarithms first: last/first itself may overflow (1e308 / 1e-3).
      points.push_back(log ? first * std::exp(t * (std::log(last) - std::log(first)))
                           : first + (last - first) * t);
    }
    require(std::all_of(points.begin(), points.end(),
                        [](double p) { return std::isfinite(p) && p > 0.0; }),
            fmt::format("sweep: first = {}, last = {} give operating points that are not finite",
                        first, last));
  }
  prm.leave_subsection();
  return points;
}

}  // namespace softglass::macro::app
