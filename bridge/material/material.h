// `bridge material`: the law at one volume fraction in SI units, as the
// material fragment of docs/material-format.md that macro scene files include.
//
// Reduced to SI. With τ = E* σ̃ and γ̇ = γ̃ E*/η_s the per-φ law
// σ̃ = σ̃_y + k̃ γ̃^m becomes τ = τ_y + K γ̇^n with
//     τ_y = E* σ̃_y,   K = E* k̃ (η_s/E*)^m,   n = m,
// and likewise N = N_y + K_N γ̇^(n_N) for N1 and N2. At a simulated φ_j,
//     ln K_j = ln E* + ln|k̃_j| + m_j L,   L = ln(η_s/E*),
//     var ln K_j = (s_k/k̃)² + L² s_m² + 2 L ρ (s_k/|k̃|) s_m,
// where ρ is the law file's correlation of ln|k̃| and m: k̃ is the value at
// γ̃ = 1, far from the data, so most of its error is the exponent's and cancels
// in K for rates near the simulated ones.
//
// Between simulated volume fractions the yield values and consistencies are
// interpolated in logarithm (they change by orders of magnitude with φ and
// keep their sign; linearly if the sign changes), the flow indices linearly,
// each with a statistical and an interpolation error (interpolation.h).
// Outside the simulated range φ is refused unless extrapolation is asked for.
// The law holds for the simulated rates only: γ̇ = γ̃ E*/η_s over the law's
// γ̃ range, stated in the file.
//
// The model has no length scale: stresses depend on φ, E*, η_s and the rate
// only, so the radius R does not enter (it enters E*, e.g. E* = 9.92 γ_i/R for
// emulsions, which the command line computes when given γ_i and R).
#pragma once

#include <string>
#include <vector>

#include "bridge/law/law.h"

namespace softglass::bridge {

struct MaterialRequest {
  double phi = 0.0;
  double modulus = 0.0;    // E* [Pa]
  double viscosity = 0.0;  // η_s [Pa s]
  bool extrapolate = false;
};

/// A value with its statistical error and interpolation error (both one
/// standard deviation, in the units of the value; interpolation NaN = unknown).
struct MaterialValue {
  double value = 0.0, statistical = 0.0, interpolation = 0.0;
  double error() const;  // in quadrature; the statistical error alone when the other is unknown
};

/// "+- 1.2 %", or, when the statistical error cannot be estimated (NaN: a law
/// of one packing per state point), "+- n/a (one packing)": never a number
/// that is only floating-point noise.
std::string relative_error_text(const MaterialValue& v);

/// N = yield + consistency γ̇^index in SI units.
struct MaterialLaw {
  MaterialValue yield, consistency, index;
};

struct Material {
  MaterialRequest request;
  PerQuantity<MaterialLaw> laws;          // sigma always, N1 and N2 when the law has them
  double rate_min = 0.0, rate_max = 0.0;  // [1/s]: the simulated γ̃ range
  std::string placement;                  // where φ lies among the simulated ones
  std::string source;                     // the prediction mode, written as `source`
};

/// InputError for a request out of range (φ outside the simulated range
/// without `extrapolate`, non-positive E* or η_s) or a result the material
/// format does not allow (a flow index outside (0, 2] after extrapolation).
Material make_material(const Law& law, const MaterialRequest& request);

/// Per-φ values interpolated at `at` (interpolation.h), in logarithm when
/// they all share a sign (they change by orders of magnitude with φ).
MaterialValue interpolate_value(const std::vector<double>& phi, const std::vector<Estimate>& v,
                                double at);

/// InputError unless φ is one of `phi` (the simulated volume fractions), or
/// lies within their range, or lies outside with `extrapolate`.
void check_phi(const std::vector<double>& phi, double at, bool extrapolate);

/// InputError for a request out of range: φ outside the simulated range
/// without `extrapolate`, non-positive or non-finite E* or η_s.
void check_request(const Law& law, const MaterialRequest& request);

/// "at the simulated volume fraction 0.85", "interpolated between …",
/// "EXTRAPOLATED from …": where φ lies among the law's.
std::string describe_placement(const Law& law, double phi);

/// "#   name = value units +- e % (statistical s %, interpolation i %)": a
/// value's band as a comment line of a material file.
std::string error_comment(const std::string& name, const MaterialValue& v, const char* units);

/// E* from a measured linear shear modulus G′ (the plateau of an amplitude or
/// frequency sweep): E* = G′ / (G0/E*)(φ), with the law's G0/E* interpolated
/// in φ like the other per-φ values; its errors carry over relatively. The
/// same range rules as make_material. For materials whose E* cannot be
/// measured directly (microgels, emulsions of unknown interfacial tension).
MaterialValue contact_modulus_from_plateau(const Law& law, double phi, double plateau_modulus,
                                           bool extrapolate);

/// E* = 9.92 γ_i/R of an emulsion's droplets (Seth et al. 2006) from the
/// interfacial tension γ_i [N/m] and the mean radius R [m]; InputError unless
/// both are positive.
double emulsion_contact_modulus(double interfacial_tension, double radius);

/// The material fragment; `provenance` lines open it as comments.
std::string material_text(const Material& material, const std::vector<std::string>& provenance);

}  // namespace softglass::bridge
