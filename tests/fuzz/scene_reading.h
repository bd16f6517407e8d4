// A scene file read in-process the way `macro run` reads it before its first
// solve (macro/app/run.cpp): the files parsed with their includes, the
// material, the solver settings and the operating points read, every entry
// and every derived scale checked (input_scales.h), the scene built (its
// constructor validates its own entries). Shared by the scene-file fuzz tests.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "macro/app/input_scales.h"
#include "macro/app/scene_file.h"
#include "macro/scenes/scene.h"

namespace softglass::macro::testing {

struct SceneAsRead {
  std::unique_ptr<Scene> scene;
  std::vector<double> points;
};

inline SceneAsRead read_scene_as_macro_run(const std::filesystem::path& file) {
  dealii::ParameterHandler prm;
  auto [material, settings, entries] = app::read_scene_input(prm, file, "", "");
  SceneAsRead read;
  read.points = app::read_sweep(prm);
  app::check_entry_scales(entries, file);
  read.scene = make_scene(prm, material, settings, file.parent_path());
  app::check_derived_scales(*read.scene, material, settings, read.points, entries, file);
  return read;
}

}  // namespace softglass::macro::testing
