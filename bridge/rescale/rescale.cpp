#include "bridge/rescale/rescale.h"

#include <fmt/format.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "bridge/rescale/curve_placement.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

// The settings against the curves (lists of one or one per curve; k' only
// matters for curves with N1).
void check(const RescaleSettings& s, const std::vector<MeasuredCurve>& measured) {
  const std::size_t curves = measured.size();
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  require(positive(s.viscosity),
          fmt::format("solvent viscosity eta_s = {} must be positive", s.viscosity));
  require(!s.modulus || positive(*s.modulus),
          fmt::format("contact modulus E* = {} must be positive", s.modulus.value_or(0)));
  const std::pair<const std::vector<double>*, const char*> lists[] = {
      {&s.yield_strain, "--yield-strain"},
      {&s.shear_modulus, "--shear-modulus"},
      {&s.yield_stress, "--yield-stress"}};
  for (const auto& [list, name] : lists) {
    require(list->size() <= 1 || list->size() == curves,
            fmt::format("{} has {} values for {} curves: give one for all, or one per curve", name,
                        list->size(), curves));
    for (double v : *list) require(positive(v), fmt::format("{} = {} must be positive", name, v));
  }
  require(s.yield_strain.empty() != s.shear_modulus.empty(),
          "give the yield strain (--yield-strain) or the shear modulus G0 (--shear-modulus), "
          "one of the two");
  require(s.min_rate < s.max_rate,
          fmt::format("the rate window {} ... {} 1/s is empty", s.min_rate, s.max_rate));
  require(positive(s.k), fmt::format("the universal constant k = {} must be positive", s.k));
  const bool with_N1 = std::any_of(measured.begin(), measured.end(), [](const MeasuredCurve& c) { return c.N1.has_value(); });
  require(!with_N1 || positive(s.k_N1),
          fmt::format("the universal constant k' = {} must be positive to place the N1 data", s.k_N1));
}

std::vector<RescaledCurve> place_all(const std::vector<MeasuredCurve>& curves,
                                     const RescaleSettings& settings) {
  std::vector<RescaledCurve> out;
  for (std::size_t j = 0; j < curves.size(); ++j)
    out.push_back(place_curve(curves[j], j, settings));
  return out;
}

double total_chi2(const std::vector<RescaledCurve>& placed) {
  double sum = 0.0;
  for (const RescaledCurve& r : placed) sum += r.chi2;
  return sum;
}

// One E* for all curves, by the profile of Σ χ²_j over ln E* (rescale.h).
std::vector<RescaledCurve> place_with_shared_modulus(const std::vector<MeasuredCurve>& curves,
                                                     RescaleSettings settings) {
  settings.shared_modulus = false;
  const std::vector<RescaledCurve> own = place_all(curves, settings);
  double low = INFINITY, high = 0.0;
  for (const RescaledCurve& r : own) {
    low = std::min(low, r.modulus.value);
    high = std::max(high, r.modulus.value);
  }
  const auto profile = [&](double log_modulus) {
    RescaleSettings at = settings;
    at.modulus = std::exp(log_modulus);
    return total_chi2(place_all(curves, at));
  };
  // The joint minimum lies between the curves' own E*; a factor 2 of margin
  // each side lets Brent's method find it when one curve dominates.
  const auto [log_modulus, minimum] =
      boost::math::tools::brent_find_minima(profile, std::log(low / 2.0), std::log(high * 2.0), 30);
  const double h = 0.01;  // in ln E*: a 1 % step, far above the minimiser's resolution
  const double curvature =
      (profile(log_modulus + h) - 2.0 * minimum + profile(log_modulus - h)) / (h * h);

  settings.modulus = std::exp(log_modulus);
  std::vector<RescaledCurve> out = place_all(curves, settings);
  double points = 0.0, parameters = 1.0;
  for (const RescaledCurve& r : out) {
    points += static_cast<double>(std::count(r.used.begin(), r.used.end(), true));
    parameters += r.yield_stress_fitted ? 1.0 : 0.0;
  }
  const double variance = minimum / (points - parameters);
  const double error = std::sqrt(2.0 * variance / curvature) * *settings.modulus;
  if (!(curvature > 0.0) || !std::isfinite(error)) {
    throw NumericalError("the shared E* is not determined: the profile of chi2 has no minimum");
  }
  for (RescaledCurve& r : out) {
    r.modulus = {*settings.modulus, error};
    r.modulus_fitted = r.modulus_shared = true;
  }
  return out;
}

}  // namespace

std::vector<RescaledCurve> rescale(const std::vector<MeasuredCurve>& curves,
                                   const RescaleSettings& settings) {
  check(settings, curves);
  require(!(settings.shared_modulus && settings.modulus),
          "a shared E* is fitted: give --modulus or --shared-modulus, not both");
  if (settings.shared_modulus) return place_with_shared_modulus(curves, settings);
  return place_all(curves, settings);
}

}  // namespace softglass::bridge
