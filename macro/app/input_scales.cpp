#include "macro/app/input_scales.h"

#include <deal.II/base/utilities.h>
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

#include "common/errors.h"

namespace softglass::macro::app {

namespace {

// What a scale is made from, to look for its cause among the entries.
enum Source : unsigned { geometry = 1, drive = 2, material = 4, flow_index = 8 };

struct Scale {
  std::string name, unit;
  double value;
  unsigned sources;
  bool may_vanish = false;  // zero is a legitimate value (no normal stresses)
  double largest = kScaleRange;
  double smallest = 1.0 / kScaleRange;
};

bool within(double value, double smallest, double largest, bool may_vanish) {
  const double a = std::abs(value);
  return std::isfinite(a) && a <= largest && (a >= smallest || (may_vanish && a == 0.0));
}

bool within(const Scale& s) { return within(s.value, s.smallest, s.largest, s.may_vanish); }

unsigned source_of(const SetEntry& e) {
  if (e.subsections.empty()) return 0;
  const std::string& s = e.subsections.front();
  if (s == "material") return e.name == "flow index" ? material | flow_index : material;
  if (s == "sweep" || s == "measurement")
    return e.name == "points" ? 0 : drive;  // a number of points is no scale
  if (s == "solver" || s == "output") return 0;
  return geometry;  // the scene's own subsection (another scene's is refused)
}

// The numbers an entry's value holds (a sweep's `values` is a list).
std::vector<double> numbers_in(const std::string& value) {
  std::vector<double> numbers;
  for (const std::string& item : dealii::Utilities::split_string_list(value)) {
    try {
      numbers.push_back(dealii::Utilities::string_to_double(item));
    } catch (const dealii::ExceptionBase&) {
      // not a number: a selection, a file name
    }
  }
  return numbers;
}

// "key = value (line L of file 'F')".
std::string located(const SetEntry& e, double value) {
  return e.line > 0 ? fmt::format("{} = {} (line {} of file '{}')", e.key(), value, e.line, e.file)
                    : fmt::format("{} = {} (file '{}')", e.key(), value, e.file);
}

// Of the entries the scale is made from, the one whose value lies farthest
// from 1 in order of magnitude, as "key = value (line L of file 'F')".
std::optional<std::string> likely_cause(const Scale& scale, const std::vector<SetEntry>& entries) {
  double farthest = -1.0;
  std::optional<std::string> cause;
  for (const SetEntry& e : entries) {
    if ((source_of(e) & scale.sources) == 0) continue;
    for (const double v : numbers_in(e.value)) {
      const double distance = v == 0.0 ? 0.0 : std::abs(std::log10(std::abs(v)));
      if (distance <= farthest) continue;
      farthest = distance;
      cause = located(e, v);
    }
  }
  return cause;
}

[[noreturn]] void refuse(const Scale& scale, const std::string& where,
                         const std::vector<SetEntry>& entries,
                         const std::filesystem::path& scene_file) {
  const std::optional<std::string> cause = likely_cause(scale, entries);
  const bool representable_range = scale.largest == kScaleRange;
  const std::string beyond = representable_range
                                 ? "what a solve can represent"
                                 : "the range the solver is measured to converge on";
  const std::string allowed =
      representable_range
          ? fmt::format("values whose derived scales (mesh sizes, rates, stresses, viscosity, "
                        "power, output) stay between {:g} and {:g} in SI units",
                        1.0 / kScaleRange, kScaleRange)
          : scale.smallest > 0.0
                ? fmt::format("{} from {:g} to {:g}", scale.name, scale.smallest, scale.largest)
                : fmt::format("{} up to {:g}", scale.name, scale.largest);
  throw InputError(fmt::format("scene file '{}': {} = {:.3g} [{}]{} is beyond {}; {}; allowed: {}",
                               scene_file.string(), scale.name, scale.value, scale.unit, where,
                               beyond,
                               cause ? "it comes from " + *cause
                                     : "it comes from the scene's entries",
                               allowed));
}

// The scales of one operating point.
std::vector<Scale> point_scales(const Scene& scene, const Material& m,
                                const fe::SolverSettings& settings, double point, double volume) {
  const double rate = scene.characteristic_rate(point);
  const double epsilon = settings.relative_rate_scale * rate;
  const double stress = m.shear->stress(rate);
  const double power = stress * rate * volume;
  const Column output = scene.columns().front();
  // Δ(γ̇_c) as such: τ(γ̇_c) − τ_y would lose it entirely beyond Bi ~ 1e16.
  const double tau_y = m.shear->yield_stress();
  const double bingham = tau_y == 0.0 ? 0.0 : tau_y / m.shear->excess_stress(rate);
  return {
      {"characteristic shear rate gamma_c", "1/s", rate, geometry | drive},
      {"regularisation rate scale eps", "1/s", epsilon, geometry | drive},
      {"stress scale tau(gamma_c)", "Pa", stress, geometry | drive | material},
      {"viscosity scale eta(eps)", "Pa s", m.shear->viscosity(epsilon), geometry | drive | material},
      {"power scale tau gamma_c V", "W", power, geometry | drive | material},
      {fmt::format("{} scale (power / {})", output.name, scene.drive().name), output.unit,
       power / point, geometry | drive | material},
      {"normal stress scale |N1| + |N2|", "Pa",
       std::abs(m.first_normal_stress_difference->value(rate)) +
           std::abs(m.second_normal_stress_difference->value(rate)),
       geometry | drive | material, true},
      {"Bingham number tau_y/(K gamma_c^n)", "1", bingham, geometry | drive | material,
       true, kLargestBinghamNumber, 0.0},
  };
}

}  // namespace

void check_entry_scales(const std::vector<SetEntry>& entries,
                        const std::filesystem::path& scene_file) {
  for (const SetEntry& e : entries) {
    if (source_of(e) == 0) continue;
    for (const double v : numbers_in(e.value)) {
      if (within(v, 1.0 / kScaleRange, kScaleRange, true)) continue;
      throw InputError(fmt::format(
          "scene file '{}': {} is beyond what a solve can represent; allowed: 0 or magnitudes "
          "between {:g} and {:g} in SI units",
          scene_file.string(), located(e, v), 1.0 / kScaleRange, kScaleRange));
    }
  }
}

void check_derived_scales(const Scene& scene, const Material& material,
                          const fe::SolverSettings& settings, const std::vector<double>& points,
                          const std::vector<SetEntry>& entries,
                          const std::filesystem::path& scene_file) {
  const MeshExtent mesh = scene.mesh_extent();
  std::vector<Scale> scales{{"smallest mesh cell", "m", mesh.smallest_cell, geometry},
                            {"mesh extent", "m", mesh.largest_extent, geometry},
                            {"volume", "m^3", mesh.volume, geometry}};
  const auto [n_min, n_max] = material.shear->flow_index_range();
  for (const double n : {n_min, n_max})
    scales.push_back(
        {"flow index n", "1", n, flow_index, false, kLargestFlowIndex, kSmallestFlowIndex});
  if (const auto instrument = scene.instrument()) {
    scales.push_back({"instrument strain constant", "1/rad", instrument->strain_constant, geometry});
    scales.push_back(
        {"instrument stress constant", "Pa/(N m)", instrument->stress_constant, geometry});
  }
  for (const Scale& s : scales)
    if (!within(s)) refuse(s, "", entries, scene_file);
  const Column drive = scene.drive();
  for (const double point : points) {
    for (const Scale& s : point_scales(scene, material, settings, point, mesh.volume)) {
      if (!within(s))
        refuse(s, fmt::format(" at {} = {:g} [{}]", drive.name, point, drive.unit), entries,
               scene_file);
    }
  }
}

}  // namespace softglass::macro::app
