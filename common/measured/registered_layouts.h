// Every layout of measured files, one line each, in the order they are tried
// (the first that recognises a header reads the file; `long`, which takes any
// header, comes last): the name of the function in the layout's own file that
// returns its registry entry (LayoutEntry <name>_layout()).
#pragma once

#define SOFTGLASS_MEASURED_LAYOUTS(LAYOUT) \
  LAYOUT(paired)                           \
  LAYOUT(long)
