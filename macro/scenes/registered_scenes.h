// Every scene, one line each: the name of the function in the scene's file
// that returns its registry entry (SceneEntry <name>_scene()). scene.cpp
// declares them and builds the registry from this list, in the order `set
// scene` lists them.
#pragma once

#define SOFTGLASS_SCENES(SCENE) \
  SCENE(channel)                \
  SCENE(pipe)                   \
  SCENE(duct)                   \
  SCENE(couette)                \
  SCENE(cone_plate)             \
  SCENE(parallel_plates)        \
  SCENE(cavity)                 \
  SCENE(obstacle)               \
  SCENE(contraction)            \
  SCENE(cylinder)
