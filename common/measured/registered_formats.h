// Every export format of measured files, one line each, in the order `auto`
// tries them (the first that recognises a text reads it; `delimited`, which
// takes any text, comes last): the name of the function in the format's own
// file that returns its registry entry (FormatEntry <name>_format()).
#pragma once

#define SOFTGLASS_MEASURED_FORMATS(FORMAT) \
  FORMAT(trios)                            \
  FORMAT(rheocompass)                      \
  FORMAT(plain)                            \
  FORMAT(delimited)
