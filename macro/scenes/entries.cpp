#include "macro/scenes/entries.h"

#include <deal.II/base/parameter_handler.h>
#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"

namespace softglass::macro::entries {

namespace {

double checked(const dealii::ParameterHandler& prm, const std::string& scene,
               const std::string& entry, const std::string& unit, bool ok(double, double, double),
               double lo, double hi, const std::string& allowed) {
  // The pattern accepts text that is no finite double (1e-320, 1e999); deal.II
  // then refuses to convert it, which is bad input like any other value.
  double value = NAN;
  try {
    value = prm.get_double(entry);
  } catch (const dealii::ExceptionBase&) {
  }
  require(std::isfinite(value) && ok(value, lo, hi),
          fmt::format("{}: {} = {} [{}] is not allowed; allowed: {} [{}]", scene, entry,
                      prm.get(entry), unit, allowed, unit));
  return value;
}

}  // namespace

double positive(const dealii::ParameterHandler& prm, const std::string& scene,
                const std::string& entry, const std::string& unit) {
  return checked(
      prm, scene, entry, unit, [](double v, double, double) { return v > 0.0; }, 0, 0, "> 0");
}

double non_negative(const dealii::ParameterHandler& prm, const std::string& scene,
                    const std::string& entry, const std::string& unit) {
  return checked(
      prm, scene, entry, unit, [](double v, double, double) { return v >= 0.0; }, 0, 0, ">= 0");
}

double between(const dealii::ParameterHandler& prm, const std::string& scene,
               const std::string& entry, const std::string& unit, double lo, double hi) {
  return checked(
      prm, scene, entry, unit, [](double v, double a, double b) { return v > a && v < b; }, lo, hi,
      fmt::format("between {} and {} (exclusive)", lo, hi));
}

}  // namespace softglass::macro::entries
