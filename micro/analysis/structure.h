// The structure of a sheared soft glass and its link to the stress
// (docs/structure.md, the paper's Fig. 3).
//
// Pair distribution, expanded in real orthonormal spherical harmonics with the
// polar axis along z (vorticity), l = 0 and 2:
//     Y00 = 1/(2√π),            Y2,±1: ½√(15/π) (ŷẑ, x̂ẑ),
//     Y2,−2 = ½√(15/π) x̂ŷ,      Y2,0 = ¼√(5/π)(3ẑ² − 1),   Y2,2 = ¼√(15/π)(x̂² − ŷ²),
// estimated per radial shell as
//     g_lm(r) = Σ_{ordered pairs in the shell} Y_lm(r̂) / (N n v(r)),   v = (r_hi³ − r_lo³)/3 ≈ r²Δr,
// so g00 = √(4π) ḡ. For a force depending on r alone the elastic stress follows:
//     σ^e_xy = −n² √(π/15) ∫ r³ f g_{2,−2} dr,   N1^e = −2n² √(π/15) ∫ r³ f g_{2,2} dr,
//     N2^e = n² ∫ r³ f [√(π/5) g_{2,0} + √(π/15) g_{2,2}] dr.
// With polydisperse radii the force is not a function of r; the force-weighted
// moments
//     (fg)_lm(r) = Σ_{ordered pairs in the shell} f r_pair Y_lm(r̂) / (N n r v(r)),
// with the shell integral ∫ r³ h dr taken as Σ r v(r) h(r), turn the same
// formulas into the virial exactly (to round-off).
//
// The number-weighted g_lm with the force f(r) between two particles of the mean
// radius give the same formulas' monodisperse value (`*_law`): exact, up to the
// binning, when all radii are equal.
//
// r_m is the radius of the minimum of g_{2,−2}, f_m the elastic force at r_m
// between two particles of the mean radius, Σ_m = −n²√(π/15) ∫ r³ g_{2,−2} dr over
// the contiguous region around r_m where g_{2,−2} < 0, so that σ^e ≈ f_m Σ_m.
//
// Time averages run over configuration snapshots of the stationary part of a
// run; errors come from `batches` consecutive batches of snapshots: per-bin
// errors from the spread of batch means, derived quantities (r_m, Σ_m, the
// rebuilt stresses) by the jackknife over batches.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

#include "micro/contact/contact_law.h"
#include "micro/geometry/lees_edwards_box.h"

namespace softglass::micro {

struct StructureSettings {
  double bin_width = 0.02;     // Δr of g_lm(r), units of R
  double range = 3.0;          // largest r
  double slab = 0.25;          // g(r, θ) from pairs with |z| < slab (units of R)
  double map_bin_width = 0.05; // Δr of the g(r, θ) map
  int angle_bins = 72;         // Δθ = 5°
  int batches = 16;            // for error estimates

  void validate() const;
};

/// The harmonics in storage order.
inline constexpr std::array<const char*, 6> kHarmonicNames = {"g00", "g2m2", "g2m1", "g20", "g21", "g22"};

/// One configuration's contributions, unnormalised, so that they add up.
struct StructureSample {
  std::vector<double> harmonics;  // [bin][6]: Σ Y_lm over ordered pairs
  std::vector<double> forces;     // [bin][6]: Σ f r_pair Y_lm over ordered pairs
  std::vector<double> map;        // [r bin][θ bin]: ordered pairs in the slab
  Eigen::Matrix3d virial = Eigen::Matrix3d::Zero();  // Σ_pairs d ⊗ f, elastic

  StructureSample& operator+=(const StructureSample& other);
};

/// The contributions of one configuration (positions in the cell or not,
/// radii, cell at its strain).
StructureSample sample_structure(const LeesEdwardsBox& box, std::span<const Vec3> x,
                                 std::span<const double> radius, const ContactLaw& law,
                                 const StructureSettings& settings);

struct Estimate {
  double value = 0.0, error = 0.0;
};

struct StructureResult {
  StructureSettings settings;
  std::size_t snapshots = 0;
  double number_density = 0.0;                  // n = N/V
  std::vector<double> r;                        // bin centres
  std::array<std::vector<double>, 6> g, g_error;         // g_lm(r)
  std::array<std::vector<double>, 6> fg, fg_error;       // (fg)_lm(r)
  std::vector<double> map_r, map_theta, map;    // g(r, θ), [r][θ], θ from the flow axis
  Estimate r_m, f_m, sigma_m, fm_sigma_m;       // the paper's σ^e ≈ f_m Σ_m
  Estimate sigma_virial, n1_virial, n2_virial;  // elastic stress, virial
  Estimate sigma_rebuilt, n1_rebuilt, n2_rebuilt;  // from the force-weighted moments
  Estimate sigma_law, n1_law, n2_law;  // from g_lm with the mean-radius force f(r): exact when monodisperse
};

/// The scalar results of a StructureResult with their names (those of the run
/// file's /structure group), units and meaning: one list for every writer.
struct NamedEstimate {
  const char* name;
  Estimate estimate;
  const char* units;
  const char* meaning;
};
std::vector<NamedEstimate> named_estimates(const StructureResult& s);

/// Averages samples (one per snapshot, in time order) of N particles in a
/// cell of volume `volume`; `law` gives f_m.
StructureResult average_structure(std::span<const StructureSample> samples, std::size_t particles,
                                  double volume, const ContactLaw& law,
                                  const StructureSettings& settings);

}  // namespace softglass::micro
