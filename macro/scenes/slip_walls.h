// Which walls of a scene slip: the `slip walls` entry of the scene's
// subsection, a list of the scene's own wall names (bob and cup, cone and
// plate, ...; the empty list, the default, is no slip anywhere), and the slip
// law of `subsection slip` (material/slip_parameters.h) they all follow. A
// name that is not one of the scene's walls is refused when the file is read
// (the entry's pattern lists the allowed names).
#pragma once

#include <deal.II/base/types.h>

#include <string>
#include <vector>

#include "macro/fe/scalar_problem.h"

namespace dealii {
class ParameterHandler;
}

namespace softglass::macro {

/// A wall that may slip: its name in `slip walls` and its boundary id.
struct Wall {
  std::string name;
  dealii::types::boundary_id id;
};

/// Declares `slip walls` in the current subsection (the scene's).
void declare_slip_walls(dealii::ParameterHandler& prm, const std::vector<Wall>& walls);

/// The walls subsection `scene` names in `slip walls` (read from the top
/// level of `prm`), with the law of `subsection slip` if there are any, to be
/// regularised at ε_V = ε · `length` (fe::WallSlip).
fe::WallSlip read_slip_walls(dealii::ParameterHandler& prm, const std::string& scene,
                             const std::vector<Wall>& walls, double length);

/// " (slip at the bob, cup)" for a scene's description; empty without slip.
std::string slip_description(const fe::WallSlip& slip, const std::vector<Wall>& walls);

}  // namespace softglass::macro
