// Every material model, one line each: the name of the function in its own
// file that returns its registry entry (MaterialModelEntry <name>_model()).
// material_model.cpp declares them and builds the registry from this list.
#pragma once

#define SOFTGLASS_MATERIAL_MODELS(MODEL) \
  MODEL(herschel_bulkley)                \
  MODEL(bingham)                         \
  MODEL(power_law)                       \
  MODEL(newtonian)                       \
  MODEL(tabulated)
