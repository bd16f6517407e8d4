// Every time integrator, one line each: the name of the function in the
// scheme's own file that returns its registry entry (IntegratorEntry
// <name>_integrator()). integrator.cpp declares them and builds the registry
// from this list; the parameter file's `scheme` accepts `auto` and these.
#pragma once

#define SOFTGLASS_INTEGRATORS(INTEGRATOR) \
  INTEGRATOR(euler)                       \
  INTEGRATOR(implicit)                    \
  INTEGRATOR(bdf2)
