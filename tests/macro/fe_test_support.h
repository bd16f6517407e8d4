// Running a scene from scene-file text, as `macro run` does, for the
// finite-element tests.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

#include "common/parameter_input.h"
#include "macro/app/scene_file.h"
#include "macro/material/material_parameters.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::testing {

/// The scene's result row at each drive; `text` is a scene file without sweep.
inline std::vector<std::vector<double>> run_scene(const std::string& text,
                                                  const std::vector<double>& drives) {
  dealii::ParameterHandler prm;
  app::declare_scene_file(prm);
  parse_parameter_text(prm, text, "test scene");
  const auto scene = make_scene(prm, read_material(prm), fe::read_solver_settings(prm), ".");
  std::vector<std::vector<double>> rows;
  for (double d : drives) rows.push_back(scene->solve(d).values());
  return rows;
}

/// A material fragment.
inline std::string material(double tau_y, double K, double n) {
  const char* model = tau_y == 0.0 ? (n == 1.0 ? "newtonian" : "power-law")
                                   : (n == 1.0 ? "bingham" : "herschel-bulkley");
  return "subsection material\n set model = " + std::string(model) +
         "\n set yield stress = " + std::to_string(tau_y) +
         "\n set consistency = " + std::to_string(K) + "\n set flow index = " + std::to_string(n) +
         "\nend\n";
}

// Columns of the rows (reduced_scene.cpp): the primary output, its two error
// estimates, then the ideal geometry's closed form and the relative deviation.
inline constexpr int kValue = 0, kDiscretisation = 1, kRegularisation = 2, kIdeal = 3,
                     kDeviation = 4;

}  // namespace softglass::macro::testing
