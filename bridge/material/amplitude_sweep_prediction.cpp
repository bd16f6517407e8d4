#include "bridge/material/amplitude_sweep_prediction.h"

#include <fmt/format.h>

#include <cmath>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

const AmplitudeSweepLaw& sweep_of(const Law& law) {
  require(law.amplitude_sweep.has_value(),
          "the law file has no amplitude sweep (subsection law/amplitude sweep): make it with "
          "`micro oscillate` and `bridge fit ... --oscillation TABLE.csv`");
  return *law.amplitude_sweep;
}

MaterialValue scaled(const MaterialValue& v, double factor) {
  return {v.value * factor, v.statistical * std::abs(factor), v.interpolation * std::abs(factor)};
}

// A strain that may be "not reached" (0) at some φ: interpolated over the
// sweep's volume fractions when every one of them reached it, else 0.
MaterialValue strain_at(const AmplitudeSweepLaw& a, const std::vector<Estimate>& strains,
                        double phi) {
  for (const Estimate& e : strains)
    if (!(e.value > 0.0)) return {0.0, 0.0, 0.0};
  return interpolate_value(a.phi, strains, phi);
}

}  // namespace

AmplitudeSweepPrediction predict_amplitude_sweep(const Law& law, const MaterialRequest& request) {
  const AmplitudeSweepLaw& a = sweep_of(law);
  require(request.modulus > 0 && std::isfinite(request.modulus),
          fmt::format("contact modulus E* = {} Pa must be positive", request.modulus));
  require(request.viscosity > 0 && std::isfinite(request.viscosity),
          fmt::format("solvent viscosity eta_s = {} Pa s must be positive", request.viscosity));
  check_phi(a.phi, request.phi, request.extrapolate);
  AmplitudeSweepPrediction p;
  p.reduced_frequency = a.frequency;
  p.angular_frequency = a.frequency * request.modulus / request.viscosity;
  p.amplitudes = a.amplitudes;
  for (std::size_t k = 0; k < a.amplitudes.size(); ++k) {
    std::vector<Estimate> storage, loss;
    for (std::size_t i = 0; i < a.phi.size(); ++i) {
      storage.push_back(a.storage[i][k]);
      loss.push_back(a.loss[i][k]);
    }
    p.storage.push_back(scaled(interpolate_value(a.phi, storage, request.phi), request.modulus));
    p.loss.push_back(scaled(interpolate_value(a.phi, loss, request.phi), request.modulus));
  }
  p.plateau_storage = p.storage.front();
  p.plateau_loss = p.loss.front();
  p.softening_strain = strain_at(a, a.softening_strain, request.phi);
  p.crossover_strain = strain_at(a, a.crossover_strain, request.phi);
  return p;
}

MaterialValue contact_modulus_from_amplitude_sweep(const Law& law, double phi,
                                                   double plateau_modulus, bool extrapolate) {
  const AmplitudeSweepLaw& a = sweep_of(law);
  require(plateau_modulus > 0 && std::isfinite(plateau_modulus),
          fmt::format("plateau modulus G' = {} Pa must be positive", plateau_modulus));
  check_phi(a.phi, phi, extrapolate);
  const MaterialValue g = interpolate_value(a.phi, a.plateau_storage, phi);
  const double e_star = plateau_modulus / g.value;
  return {e_star, e_star * g.statistical / g.value, e_star * g.interpolation / g.value};
}

}  // namespace softglass::bridge
