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

namespace softglass::macro {

namespace {

namespace Patterns = dealii::Patterns;

constexpr const char* kSubsection = "material";
// Entries every file must set (the shear law in full).
constexpr std::array kRequired{"model", "yield stress", "consistency", "flow index"};

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

void declare_normal_stress(dealii::ParameterHandler& prm, const std::string& name,
                           const std::string& difference) {
  prm.declare_entry(name + " yield", "0", Patterns::Double(),
                    "N_y of " + difference + " = N_y + K_N gamma_dot^n_N [Pa]; any finite value.");
  prm.declare_entry(name + " consistency", "0", Patterns::Double(),
                    "K_N [Pa s^n_N]; any finite value (0: no rate dependence).");
  prm.declare_entry(name + " flow index", "1", Patterns::Double(), "n_N [1]; > 0.");
}

NormalStressLaw normal_stress(const dealii::ParameterHandler& prm, const std::string& name) {
  return {.yield = prm.get_double(name + " yield"),
          .consistency = prm.get_double(name + " consistency"),
          .flow_index = prm.get_double(name + " flow index")};
}

}  // namespace

void declare_material(dealii::ParameterHandler& prm) {
  prm.enter_subsection(kSubsection);
  prm.declare_entry("model", "herschel-bulkley",
                    Patterns::Selection(fmt::format("{}", fmt::join(model_names(), "|"))),
                    "Shear law tau = tau_y + K gamma_dot^n above the yield stress: "
                    "herschel-bulkley, bingham (n = 1), power-law (tau_y = 0) or newtonian "
                    "(both). Required.",
                    true);
  prm.declare_entry("yield stress", "0", Patterns::Double(),
                    "tau_y [Pa]; >= 0, and 0 for power-law and newtonian. Required.", true);
  prm.declare_entry("consistency", "1", Patterns::Double(),
                    "K [Pa s^n] (the viscosity for bingham and newtonian); > 0. Required.", true);
  prm.declare_entry("flow index", "1", Patterns::Double(),
                    "n [1]; 0 < n <= 2, and 1 for bingham and newtonian. Required.", true);
  declare_normal_stress(prm, "N1", "the first normal stress difference N1");
  declare_normal_stress(prm, "N2", "the second normal stress difference N2");
  prm.leave_subsection();
}

void set_material(dealii::ParameterHandler& prm, const Material& material) {
  prm.enter_subsection(kSubsection);
  prm.set("model", std::string(model_name(material.model)));
  prm.set("yield stress", material.shear.yield_stress);
  prm.set("consistency", material.shear.consistency);
  prm.set("flow index", material.shear.flow_index);
  for (const auto& [name, law] : {std::pair{"N1", material.first_normal_stress_difference},
                                  std::pair{"N2", material.second_normal_stress_difference}}) {
    prm.set(fmt::format("{} yield", name), law.yield);
    prm.set(fmt::format("{} consistency", name), law.consistency);
    prm.set(fmt::format("{} flow index", name), law.flow_index);
  }
  prm.leave_subsection();
}

Material read_material(dealii::ParameterHandler& prm) {
  std::vector<std::string> missing;
  for (const std::string& path : prm.get_entries_wrongly_not_set()) {
    const std::string name = demangle(path);
    for (const char* required : kRequired) {
      if (name == fmt::format("{}.{}", kSubsection, required)) missing.push_back(required);
    }
  }
  require(missing.empty(),
          fmt::format("material: required entries not set: '{}'", fmt::join(missing, "', '")));
  Material material;
  prm.enter_subsection(kSubsection);
  try {
    material.model = parse_flow_model(prm.get("model"));
    material.shear = {.yield_stress = prm.get_double("yield stress"),
                      .consistency = prm.get_double("consistency"),
                      .flow_index = prm.get_double("flow index")};
    material.first_normal_stress_difference = normal_stress(prm, "N1");
    material.second_normal_stress_difference = normal_stress(prm, "N2");
  } catch (const dealii::ExceptionBase& error) {
    // A value the pattern accepts but the conversion cannot represent (1e-400).
    prm.leave_subsection();
    throw InputError(fmt::format("material: {}", deal_ii_message(error.what())));
  }
  prm.leave_subsection();
  validate(material);
  return material;
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
