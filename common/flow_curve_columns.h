// The columns of the flow-curve tables (docs/flow-curve-format.md): micro
// writes them, bridge reads them, and both take the names and units from here
// so that the two tools cannot drift apart.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace softglass::flow_curve {

inline constexpr const char* phi = "phi";
inline constexpr const char* gamma_tilde = "gamma_tilde";
inline constexpr const char* packings = "packings";    ///< runs averaged in the row
inline constexpr const char* seed = "seed";            ///< per-packing table: the run's packing
inline constexpr const char* converged = "converged";  ///< runs that met the stopping rule
inline constexpr const char* coordination = "Z";
inline constexpr const char* shear_modulus = "G0";
inline constexpr const char* contact_distance = "r_m";  ///< peak of g(r) (docs/structure.md)
inline constexpr const char* contact_force = "f_m";     ///< force at the peak

inline constexpr const char* shear_stress = "sigma";
inline constexpr const char* first_normal_difference = "N1";
inline constexpr const char* second_normal_difference = "N2";

/// The stress columns, in table order; each is followed by its standard error.
/// "_film" is the EHD films' part of "_viscous" (the paper's σ^v).
inline constexpr std::array<const char*, 13> stresses = {
    shear_stress,       "sigma_elastic", "sigma_viscous", "sigma_film",
    first_normal_difference, "N1_elastic", "N1_viscous", "N1_film",
    second_normal_difference, "N2_elastic", "N2_viscous", "N2_film",
    "pressure"};

/// The standard error of column `name`.
inline std::string error_of(std::string_view name) { return std::string(name) + "_se"; }

/// The unit of a column of the format, errors included ("1", "E*", "E*R^2",
/// "R"); "" for a name the format does not define.
std::string unit_of(std::string_view name);

}  // namespace softglass::flow_curve
