// Every contact law, one line each: the name of the function in the law's own
// file that returns its registry entry (ContactLawEntry <name>_law()).
// contact_law.cpp declares them and builds the registry from this list.
#pragma once

#define SOFTGLASS_CONTACT_LAWS(LAW) \
  LAW(seth2011)                     \
  LAW(hertz)                        \
  LAW(piecewise)                    \
  LAW(power)                        \
  LAW(table)
