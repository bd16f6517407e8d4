#include "bridge/sweep/sweep_fit.h"

#include <cmath>

namespace softglass::bridge {

namespace {

constexpr std::array<Quantity, 3> kStresses = {Quantity::sigma, Quantity::N1, Quantity::N2};

HbParameters usable(const HerschelBulkleyFit& fit) {
  return fit.converged ? fit.parameters : HbParameters{kNaN, kNaN, kNaN};
}

}  // namespace

SweepFitOutcome fit_sweep(const Sweep& sweep) {
  SweepFitOutcome out;
  SweepFit& fit = out.fit;
  FitDiagnostics& diagnostics = out.diagnostics;
  diagnostics.hb.resize(sweep.groups.size());

  for (std::size_t j = 0; j < sweep.groups.size(); ++j) {
    const PhiGroup& g = sweep.groups[j];
    GroupFit& f = fit.groups.emplace_back();
    f.phi = g.phi;
    f.modulus = g.modulus.value;
    for (Quantity q : kAllQuantities) {
      if (!g.curves[index(q)]) continue;
      const HerschelBulkleyFit& hb =
          diagnostics.hb[j][index(q)].emplace(fit_herschel_bulkley(*g.curves[index(q)]));
      f.hb[index(q)] = usable(hb);
    }
    f.yield_strain = f.hb[index(Quantity::sigma)]->yield / f.modulus;
  }

  // The universal laws; the σ law's yield stresses give the yield strains γ_y of
  // the collapse variable γ̃/γ_y² (the normal laws do not need them: σ_y/γ_y = G0).
  std::vector<double> moduli;
  for (const PhiGroup& g : sweep.groups) moduli.push_back(g.modulus.value);
  for (Quantity q : kStresses) {
    if (!sweep.present[index(q)]) continue;
    std::vector<const Curve*> curves;
    for (const PhiGroup& g : sweep.groups) curves.push_back(&*g.curves[index(q)]);
    const UniversalFit& law = diagnostics.universal[index(q)].emplace(
        fit_universal_law(curves, moduli, universal_sign(q)));
    fit.k[index(q)] = law.converged ? law.k : kNaN;
    for (std::size_t j = 0; j < sweep.groups.size(); ++j)
      fit.groups[j].universal_yield[index(q)] = law.converged ? law.yield[j] : kNaN;
  }
  for (GroupFit& f : fit.groups)
    f.universal_yield_strain = *f.universal_yield[index(Quantity::sigma)] / f.modulus;

  // Each φ's own constant from its m = ½ law: the collapse checked φ by φ.
  for (std::size_t j = 0; j < sweep.groups.size(); ++j) {
    GroupFit& f = fit.groups[j];
    for (Quantity q : kStresses) {
      if (!sweep.present[index(q)]) continue;
      const SquareRootLaw law = fit_square_root_law(*sweep.groups[j].curves[index(q)]);
      f.own_k[index(q)] = universal_sign(q) * law.slope / f.modulus;
    }
  }

  if (sweep.present[index(Quantity::force)]) {
    for (std::size_t j = 0; j < sweep.groups.size(); ++j) {
      const SquareRootLaw law =
          fit_square_root_law(*sweep.groups[j].curves[index(Quantity::force)]);
      fit.groups[j].force_yield = law.intercept;
      fit.groups[j].force_slope = law.slope;
    }
  }

  double sum = 0.0;
  for (const GroupFit& f : fit.groups) sum += f.hb[index(Quantity::sigma)]->exponent;
  fit.mean_exponent = sum / static_cast<double>(fit.groups.size());
  return out;
}

}  // namespace softglass::bridge
