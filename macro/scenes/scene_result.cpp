#include "macro/scenes/scene_result.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace softglass::macro {

namespace {

// pack(): an optional as a presence flag and its value.
void pack_optional(std::vector<double>& out, const std::optional<double>& value) {
  out.insert(out.end(), {value ? 1.0 : 0.0, value.value_or(0.0)});
}

std::optional<double> unpack_optional(const double*& in) {
  const bool present = in[0] != 0.0;
  const double value = in[1];
  in += 2;
  return present ? std::optional<double>(value) : std::nullopt;
}

}  // namespace

const Estimate& SceneResult::torque() const {
  if (quantity != MainQuantity::torque) throw std::logic_error("the scene reports no torque");
  return main;
}

std::vector<double> SceneResult::values() const {
  std::vector<double> row{main.value, main.discretisation_error, main.regularisation_error};
  if (ideal_geometry) {
    const double ideal = *ideal_geometry;
    row.push_back(ideal);
    row.push_back(ideal != 0.0 ? main.value / ideal - 1.0
                               : std::numeric_limits<double>::quiet_NaN());
  }
  if (normal_force) row.push_back(*normal_force);
  if (max_velocity) row.push_back(*max_velocity);
  row.insert(row.end(), own.begin(), own.end());
  row.insert(row.end(), {yielded_fraction, double(cost.cells), double(cost.dofs),
                         double(cost.iterations), cost.wall_time});
  return row;
}

std::vector<double> SceneResult::pack() const {
  std::vector<double> out{double(quantity), main.value, main.discretisation_error,
                          main.regularisation_error};
  pack_optional(out, ideal_geometry);
  pack_optional(out, normal_force);
  pack_optional(out, max_velocity);
  out.insert(out.end(), {yielded_fraction, double(cost.cells), double(cost.dofs),
                         double(cost.iterations), cost.wall_time, double(own.size())});
  out.insert(out.end(), own.begin(), own.end());
  return out;
}

SceneResult SceneResult::unpack(const std::vector<double>& packed) {
  const double* in = packed.data();
  SceneResult r;
  r.quantity = MainQuantity(int(in[0]));
  r.main = {.value = in[1], .discretisation_error = in[2], .regularisation_error = in[3]};
  in += 4;
  r.ideal_geometry = unpack_optional(in);
  r.normal_force = unpack_optional(in);
  r.max_velocity = unpack_optional(in);
  r.yielded_fraction = in[0];
  r.cost = {.cells = unsigned(in[1]),
            .dofs = unsigned(in[2]),
            .iterations = unsigned(in[3]),
            .wall_time = in[4]};
  r.own.assign(in + 6, in + 6 + std::size_t(in[5]));
  return r;
}

}  // namespace softglass::macro
