// `subsection slip` of a scene file: the slip law of the walls a scene names
// in its `slip walls` entry (scenes/slip_walls.h), read with deal.II's
// ParameterHandler like the material fragment (material_parameters.h), and
// like it includable from a file of its own.
//
//     subsection slip
//       set law         = power-law
//       set coefficient = 2e-6      # beta [m/s/Pa^p]
//       set exponent    = 2         # p
//       set yield stress = 0        # sigma_s [Pa]
//     end
//
// The entries default to 0, which no law allows: a scene with slip walls must
// state its law's coefficients. Every problem is an InputError (exit code 2)
// naming the entry, its value and what is allowed.
#pragma once

#include <memory>

#include "macro/material/slip_law.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro {

/// Declares `subsection slip` and its entries, documented with units.
void declare_slip_law(dealii::ParameterHandler& prm);

/// The slip law `prm` states (declared by declare_slip_law), validated.
std::shared_ptr<const SlipLaw> read_slip_law(dealii::ParameterHandler& prm);

}  // namespace softglass::macro
