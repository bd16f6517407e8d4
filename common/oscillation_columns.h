// The columns of the oscillation tables (docs/oscillation.md): `micro
// oscillate` writes them, `bridge` reads them, and both take the names and
// units from here, as for the flow-curve tables (flow_curve_columns.h).
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace softglass::oscillation_table {

inline constexpr const char* phi = "phi";
inline constexpr const char* amplitude = "gamma0";        ///< strain amplitude γ0
inline constexpr const char* frequency = "omega_tilde";   ///< ω̃ = ω η_s / E*
inline constexpr const char* packings = "packings";       ///< runs averaged in the row
inline constexpr const char* seed = "seed";               ///< per-packing table: the run's packing
inline constexpr const char* converged = "converged";     ///< runs that met the stopping rule
inline constexpr const char* cycles = "periodic_cycles";  ///< cycles averaged (all runs)
inline constexpr const char* shear_modulus = "G0";        ///< static linear modulus of the packings
/// The packings' static modulus of the x–y simple shear alone: the one the
/// Lees–Edwards oscillation loads (G0 is the mean over six shears).
inline constexpr const char* flow_gradient_modulus = "G0_xy";

inline constexpr const char* storage = "storage";  ///< G′ of σ
inline constexpr const char* loss = "loss";        ///< G″ of σ

/// The responses of a cycle, in table order; each is followed by its
/// standard error in the tables. G′, G″ of σ and of its elastic, viscous and
/// film parts; the relative intensities I3/I1, I5/I1; the Chebyshev
/// coefficients e1, e3 (E*) and v1, v3 (η_s); the cycle means of N1, N2, Π.
inline constexpr std::array<const char*, 17> responses = {storage,
                                                          loss,
                                                          "storage_elastic",
                                                          "loss_elastic",
                                                          "storage_viscous",
                                                          "loss_viscous",
                                                          "storage_film",
                                                          "loss_film",
                                                          "intensity_3",
                                                          "intensity_5",
                                                          "e1",
                                                          "e3",
                                                          "v1",
                                                          "v3",
                                                          "N1",
                                                          "N2",
                                                          "pressure"};

/// The standard error of column `name`.
inline std::string error_of(std::string_view name) {
  return std::string(name) + "_se";
}

/// The unit of a column, errors included ("1", "E*", "eta_s"); "" for a name
/// the format does not define.
std::string unit_of(std::string_view name);

}  // namespace softglass::oscillation_table
