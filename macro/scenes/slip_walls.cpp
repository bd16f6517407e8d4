#include "macro/scenes/slip_walls.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "macro/material/slip_parameters.h"

namespace softglass::macro {

namespace Patterns = dealii::Patterns;

namespace {

std::vector<std::string> names(const std::vector<Wall>& walls) {
  std::vector<std::string> out;
  for (const Wall& w : walls) out.push_back(w.name);
  return out;
}

}  // namespace

void declare_slip_walls(dealii::ParameterHandler& prm, const std::vector<Wall>& walls) {
  prm.declare_entry(
      "slip walls", "",
      Patterns::List(Patterns::Selection(fmt::format("{}", fmt::join(names(walls), "|"))), 0,
                     walls.size()),
      fmt::format("the smooth walls, which slip by the law of subsection slip, named from: {} "
                  "(comma-separated; empty: no slip)",
                  fmt::join(names(walls), ", ")));
}

fe::WallSlip read_slip_walls(dealii::ParameterHandler& prm, const std::string& scene,
                             const std::vector<Wall>& walls, double length) {
  prm.enter_subsection(scene);
  const std::vector<std::string> named =
      dealii::Utilities::split_string_list(prm.get("slip walls"));
  prm.leave_subsection();
  fe::WallSlip slip;
  slip.length = length;
  for (const Wall& w : walls)
    for (const std::string& name : named)
      if (name == w.name) slip.walls.insert(w.id);
  if (!slip.walls.empty()) slip.law = read_slip_law(prm);
  return slip;
}

std::string slip_description(const fe::WallSlip& slip, const std::vector<Wall>& walls) {
  if (!slip.any()) return "";
  std::vector<std::string> slipping;
  for (const Wall& w : walls)
    if (slip.walls.count(w.id) > 0) slipping.push_back(w.name);
  return fmt::format(" (slip at the {}: {})", fmt::join(slipping, ", "), slip.law->name());
}

}  // namespace softglass::macro
