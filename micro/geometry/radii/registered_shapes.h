// Every shape of radius distribution, one line each: the name of the function
// in the shape's own file that returns its registry entry (RadiusShapeEntry
// <name>_radii()). radius_distribution.cpp builds the registry from this list.
#pragma once

#define SOFTGLASS_RADIUS_SHAPES(SHAPE) \
  SHAPE(gaussian)                      \
  SHAPE(uniform)                       \
  SHAPE(lognormal)                     \
  SHAPE(bidisperse)
