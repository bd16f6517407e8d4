// `bridge material --tabulated`: the simulated flow curve itself, at one
// volume fraction in SI units, as the tabulated material of
// docs/material-format.md (macro/material/tabulated_law.h) — the hand-off that
// keeps what the particles say at every simulated rate instead of one
// Herschel–Bulkley triple fitted over five decades.
//
// Source. `bridge fit` writes beside its law file the simulated state points
// (LAW_points.csv: σ̃, N1, N2 and their packing-bootstrap standard errors at
// each φ and γ̃) and the per-φ table (LAW_phi.csv, with the quasi-static yield
// stress σ̃_y of the γ̃ → 0 runs). Rows are the rates simulated at every φ.
//
// Interpolation in φ. At each simulated γ̃ the value at the user's φ is
// interpolated between the neighbouring simulated φ like every per-φ value of
// `bridge material` (material.h: linear in ln|value| when all share a sign,
// with the statistical error propagated and the interpolation error estimated
// from the measured curvature). Linear in ln σ̃ is a choice for monotonicity: at
// fixed weights, ln σ̃(φ, γ̃) = w_a ln σ̃_a(γ̃) + w_b ln σ̃_b(γ̃) increases with γ̃
// wherever both simulated curves do, so the interpolated flow curve is a flow
// curve; a cubic in φ would not guarantee it. Between rates, macro interpolates
// with a monotone cubic in log-log (tabulated_law.h).
//
// SI units: τ = E* σ̃, γ̇ = γ̃ E*/η_s. The yield stress is E* σ̃_y of the
// quasi-static runs; N1 and N2 at rest are the law file's fitted plateaus.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bridge/law/law.h"
#include "bridge/material/material.h"

namespace softglass::bridge {

/// The simulated points beside a law file, per volume fraction and rate.
struct SimulatedCurves {
  std::vector<double> phi;          // the law's volume fractions
  std::vector<double> gamma_tilde;  // rates simulated at every φ, increasing
  /// [quantity][rate][φ]: sigma always, N1 and N2 when the sweep had them.
  PerQuantity<std::vector<std::vector<Estimate>>> values;
  std::vector<Estimate> quasi_static_yield;  // σ̃_y per φ
};

/// Reads LAW_points.csv and LAW_phi.csv beside `law_file`; InputError naming
/// the file when one is missing or lacks a column, or when a φ of the law has
/// no quasi-static yield stress.
SimulatedCurves read_simulated_curves(const std::filesystem::path& law_file, const Law& law);

struct TabulatedRow {
  double rate = 0.0;                 // γ̇ [1/s]
  PerQuantity<MaterialValue> value;  // [Pa]: sigma always
};

struct TabulatedMaterial {
  MaterialRequest request;
  MaterialValue yield;                   // τ_y [Pa], the quasi-static limit
  PerQuantity<MaterialValue> rest;       // N1, N2 at rest [Pa] (the law's fitted plateaus)
  std::vector<TabulatedRow> rows;        // increasing rates
  std::vector<TabulatedRow> plateau_rows;  // lowest rates left out: stress not above τ_y
  std::string placement;                 // where φ lies among the simulated ones
  std::string source;                    // the prediction mode, written as `source`
};

/// The table at the request's φ, E*, η_s. The lowest rates whose stress does
/// not exceed the quasi-static yield stress lie on the yield plateau within
/// the scatter and are left out (plateau_rows). InputError for a request out
/// of range (as make_material), fewer than two rows left, or stresses that do
/// not increase with the rate (naming the rows): macro refuses such a table,
/// and the sweep should be run longer there.
TabulatedMaterial make_tabulated_material(const Law& law, const SimulatedCurves& curves,
                                          const MaterialRequest& request);

/// The material fragment; `provenance` lines open it as comments, then each
/// row's band.
std::string tabulated_material_text(const TabulatedMaterial& material,
                                    const std::vector<std::string>& provenance);

}  // namespace softglass::bridge
