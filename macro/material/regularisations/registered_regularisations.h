// Every regularisation, one line each: the name of the function in its own
// file that returns its registry entry (RegularisationEntry <name>_regularisation()).
// regularised_law.cpp declares them and builds the registry from this list.
#pragma once

#define SOFTGLASS_REGULARISATIONS(REGULARISATION) \
  REGULARISATION(papanastasiou)                   \
  REGULARISATION(bercovier_engelman)
