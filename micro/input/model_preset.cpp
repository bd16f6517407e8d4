#include "micro/input/model_preset.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "common/errors.h"

namespace softglass::micro {

namespace {

struct PresetEntry {
  const char* subsection;
  const char* name;
  const char* value;
};

struct ModelPreset {
  const char* name;
  const char* summary;
  std::vector<PresetEntry> entries;  // on top of the declarations' defaults
};

const std::vector<ModelPreset>& presets() {
  static const std::vector<ModelPreset> list = {
      {"literal",
       "the paper as stated: seth2011 contact law, Stokes friction against the affine flow",
       {{"contact law", "law", "seth2011"}, {"drag", "stokes reference", "affine"}}},
      {"softglass",
       "seth2011's branches at nominal strain (piecewise, breakpoints eps = 0.4, 0.8), the "
       "Stokes friction against the neighbours and films of rest thickness 0.002 R "
       "(docs/fidelity.md)",
       {{"contact law", "law", "piecewise"},
        {"contact law", "piecewise breakpoints", "0.4, 0.8"},
        {"contact law", "piecewise exponents", "1.5, 2, 3"},
        {"drag", "stokes reference", "neighbours"},
        {"drag", "film rest thickness", "0.002"}}},
  };
  return list;
}

}  // namespace

std::string model_preset_names() {
  std::string names;
  for (const ModelPreset& p : presets()) {
    if (!names.empty()) names += '|';
    names += p.name;
  }
  return names;
}

std::string model_preset_documentation() {
  std::string text;
  for (const ModelPreset& p : presets()) text += fmt::format(" {}: {};", p.name, p.summary);
  text.back() = '.';
  return text;
}

void apply_model_preset(dealii::ParameterHandler& prm, const std::vector<SetEntry>& set_by_file) {
  const auto set = [&](const std::string& subsection, const std::string& name) {
    return std::find_if(set_by_file.begin(), set_by_file.end(), [&](const SetEntry& e) {
      return e.subsections == std::vector<std::string>{subsection} && e.name == name;
    });
  };
  const auto chosen = set("model", "preset");
  const std::string preset = chosen != set_by_file.end() ? chosen->value : kDefaultModelPreset;
  for (const ModelPreset& p : presets()) {
    if (preset != p.name) continue;
    for (const PresetEntry& e : p.entries) {
      if (set(e.subsection, e.name) != set_by_file.end()) continue;
      prm.enter_subsection(e.subsection);
      prm.set(e.name, std::string(e.value));
      prm.leave_subsection();
    }
    return;
  }
  throw InputError(
      fmt::format("model preset '{}' is unknown; allowed: {}", preset, model_preset_names()));
}

}  // namespace softglass::micro
