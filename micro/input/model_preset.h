// Model presets: whole readings of the paper's model, chosen by one entry
// (`subsection model / set preset`) instead of entry by entry.
//
//   literal    the paper as it states it: the `seth2011` contact law (the
//              large-deformation branches at eps = h/R_c = 0.1, 0.2) and the
//              Stokes friction against the imposed affine flow.
//   softglass  two declared changes of that reading, each decided by a
//              measurement (docs/fidelity.md): seth2011's branches placed in
//              nominal strain (eps = 0.4, 0.8; G0 against compressed
//              emulsions), and the Stokes friction against the neighbours'
//              motion (pair dashpots; the exponent m and the universal k).
//
// A preset sets entries of subsections `contact law` and `drag`; any entry the
// file sets itself wins over the preset's.
#pragma once

#include <string>

namespace dealii {
class ParameterHandler;
}

namespace softglass::micro {

inline constexpr const char* kDefaultModelPreset = "literal";

/// "literal|softglass", for the parameter file.
std::string model_preset_names();
/// One line per preset, for the entry's documentation.
std::string model_preset_documentation();

/// Sets the preset's entries in `prm` (declared by parameter_file.cpp), before
/// the file is parsed. Throws InputError for an unknown name.
void apply_model_preset(dealii::ParameterHandler& prm, const std::string& preset);

}  // namespace softglass::micro
