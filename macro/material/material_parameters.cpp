#include "macro/material/material_parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <sstream>
#include <vector>

#include "common/deal_ii_message.h"
#include "common/parameter_input.h"
#include "common/errors.h"
#include "macro/material/material_model.h"

namespace softglass::macro {

namespace {

namespace Patterns = dealii::Patterns;

constexpr const char* kSubsection = "material";

// ParameterHandler reports entries by mangled path: "material.yield_20stress".
std::string demangle(const std::string& path) {
  std::string name;
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (path[k] == '_' && k + 2 < path.size()) {
      name += static_cast<char>(std::stoi(path.substr(k + 1, 2), nullptr, 16));
      k += 2;
    } else {
      name += path[k];
    }
  }
  return name;
}

}  // namespace

void declare_material(dealii::ParameterHandler& prm) {
  const auto& models = material_models();
  prm.enter_subsection(kSubsection);
  std::string summaries;
  for (const MaterialModelEntry& m : models.entries())
    summaries += fmt::format("{}{}: {}", summaries.empty() ? "" : "; ", m.name, m.summary);
  prm.declare_entry("model", "herschel-bulkley", Patterns::Selection(models.selection()),
                    fmt::format("The shear law: {}. Required.", summaries), true);
  prm.declare_entry("yield stress", "0", Patterns::Double(),
                    "tau_y [Pa]; >= 0, and 0 for power-law and newtonian (tabulated: the limit "
                    "of the flow curve at rest). Required.",
                    true);
  prm.declare_entry("source", "", Patterns::Anything(),
                    "Where the material comes from, e.g. the prediction mode `bridge material` "
                    "states; printed with every result. Optional.");
  for (const std::string name : {"N1", "N2"})
    prm.declare_entry(name + " yield", "0", Patterns::Double(),
                      "N_y, the value of " + name + " at rest [Pa]; any finite value.");
  for (const MaterialModelEntry& m : models.entries()) m.traits.declare(prm);
  prm.leave_subsection();
}

void set_material(dealii::ParameterHandler& prm, const std::vector<SetEntry>& entries) {
  for (const SetEntry& e : entries) {
    if (e.subsections != std::vector<std::string>{kSubsection}) continue;
    prm.enter_subsection(kSubsection);
    prm.set(e.name, e.value);
    prm.leave_subsection();
  }
}

Material read_material(dealii::ParameterHandler& prm) {
  prm.enter_subsection(kSubsection);
  const MaterialModelEntry& model = material_models().at(prm.get("model"));
  prm.leave_subsection();
  std::vector<std::string> missing;
  for (const std::string& path : prm.get_entries_wrongly_not_set()) {
    const std::string name = demangle(path);
    if (name == fmt::format("{}.model", kSubsection)) missing.push_back("model");
    for (const std::string& required : model.traits.required) {
      if (name == fmt::format("{}.{}", kSubsection, required)) missing.push_back(required);
    }
  }
  require(missing.empty(),
          fmt::format("material: required entries not set: '{}'", fmt::join(missing, "', '")));
  prm.enter_subsection(kSubsection);
  std::unique_ptr<Material> material;
  try {
    material = model.make(prm);
  } catch (const dealii::ExceptionBase& error) {
    // A value the pattern accepts but the conversion cannot represent (1e-400).
    prm.leave_subsection();
    throw InputError(fmt::format("material: {}", deal_ii_message(error.what())));
  } catch (...) {
    prm.leave_subsection();
    throw;
  }
  material->source = prm.get("source");
  prm.leave_subsection();
  return std::move(*material);
}

Material parse_material(const std::string& text, const std::string& source) {
  dealii::ParameterHandler prm;
  declare_material(prm);
  parse_parameter_text(prm, text, source);
  return read_material(prm);
}

MaterialFile read_material_file(const std::filesystem::path& file) {
  dealii::ParameterHandler prm;
  declare_material(prm);
  std::vector<SetEntry> entries = parse_parameter_file(prm, file, "material file");
  return {read_material(prm), std::move(entries)};
}

}  // namespace softglass::macro
