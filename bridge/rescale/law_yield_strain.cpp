#include "bridge/rescale/law_yield_strain.h"

#include <fmt/format.h>

#include <charconv>

#include "bridge/material/interpolation.h"
#include "common/errors.h"

namespace softglass::bridge {

std::vector<double> law_yield_strains(const Law& law, const std::vector<double>& phi,
                                      bool extrapolate, const std::string& source) {
  std::vector<double> strains;
  for (double at : phi) {
    require(at > 0 && at < 1, fmt::format("volume fraction phi = {} must be in (0, 1)", at));
    const bool inside = at >= law.phi.front() && at <= law.phi.back();
    require(inside || extrapolate,
            fmt::format("phi = {} is outside the range {} ... {} of the law {}; pass "
                        "--extrapolate to extrapolate its yield strain linearly",
                        at, law.phi.front(), law.phi.back(), source));
    require(is_simulated(law.phi, at) || law.phi.size() >= 2,
            fmt::format("the law {} holds for phi = {} only", source, law.phi.front()));
    const double strain = interpolate(law.phi, law.yield_strain, at).value;
    require(strain > 0,
            fmt::format("the law {} gives a yield strain {} at phi = {}", source, strain, at));
    strains.push_back(strain);
  }
  return strains;
}

std::vector<double> phi_from_labels(const std::vector<std::string>& labels) {
  std::vector<double> phi;
  for (const std::string& label : labels) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(label.data(), label.data() + label.size(), value);
    require(error == std::errc() && end == label.data() + label.size(),
            fmt::format("curve label '{}' is not a volume fraction (--phi-from-labels reads "
                        "labels such as '0.68')",
                        label));
    phi.push_back(value);
  }
  return phi;
}

}  // namespace softglass::bridge
