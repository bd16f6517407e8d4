// Every slip law, one line each: the name of the function in its own file that
// returns its registry entry (SlipLawEntry <name>_slip_law()). slip_law.cpp
// declares them and builds the registry from this list.
#pragma once

#define SOFTGLASS_SLIP_LAWS(SLIP_LAW) SLIP_LAW(power_law)
