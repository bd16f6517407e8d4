// Model presets: whole readings of the paper's model, chosen by one entry
// (`subsection model / set preset`) instead of entry by entry.
//
//   literal    the paper as it states it: the `seth2011` contact law (the
//              large-deformation branches at eps = h/R_c = 0.1, 0.2) and the
//              Stokes friction against the imposed affine flow.
//   softglass  the default: two declared changes of that reading, each
//              decided by a measurement (docs/fidelity.md): seth2011's
//              branches placed in nominal strain (eps = 0.4, 0.8; G0 against
//              compressed emulsions), and the Stokes friction against the
//              neighbours' motion (pair dashpots; the exponent m and the
//              universal k).
//
// A preset sets entries of subsections `contact law` and `drag` that the file
// does not set itself.
#pragma once

#include <string>
#include <vector>

#include "common/parameter_input.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::micro {

inline constexpr const char* kDefaultModelPreset = "softglass";

/// "literal|softglass", for the parameter file.
std::string model_preset_names();
/// One line per preset, for the entry's documentation.
std::string model_preset_documentation();

/// After a file is parsed into `prm` (declared by parameter_file.cpp): sets
/// the entries of the preset the file chooses (`model/preset` among
/// `set_by_file`, else the default) that the file does not set itself.
void apply_model_preset(dealii::ParameterHandler& prm, const std::vector<SetEntry>& set_by_file);

}  // namespace softglass::micro
