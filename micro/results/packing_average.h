// Averages over independent packings at one state point (φ, γ̃), the paper's
// protocol (docs/physics.md, "Protocol": five packings per point).
//
// For each observable the packing average is the mean of the runs' means. Two
// standard errors are reported: `within` from the runs' own (blocking) errors,
// √(Σ SE_k²)/K, which knows only the time noise; and `between`, the standard
// deviation of the run means over √K, which also holds the packing-to-packing
// (disorder) scatter but is itself uncertain for few packings. The quoted error
// is the larger of the two.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "micro/io/run_file.h"

namespace softglass::micro {

struct AveragedObservable {
  std::string name;
  double mean = 0.0;
  double within = 0.0;   // from the runs' own standard errors
  double between = 0.0;  // from the scatter of the run means (0 for one run)
  double standard_error() const { return std::max(within, between); }
};

struct PackingAverage {
  std::size_t runs = 0, converged_runs = 0, particles = 0;
  double gamma_tilde = 0.0, volume_fraction = 0.0;
  double shear_modulus = 0.0, shear_modulus_error = 0.0;  // mean and SE over packings
  double averaged_strain = 0.0;                           // total over runs
  double coordination = 0.0;                              // mean Z under shear
  std::vector<AveragedObservable> observables;            // shear_observable_names() order
  std::optional<AveragedObservable> r_m, f_m;             // when every run has its structure

  const AveragedObservable& operator[](const std::string& name) const;
};

/// Whether two state variables (φ, γ̃, γ0, ω̃) of runs are the same, to a
/// relative 1e-9 (their files store them from the same numbers).
bool same_state(double a, double b);

/// The mean over runs of one observable, with `within` from the runs' own
/// errors and `between` from the scatter of their means.
AveragedObservable average(const std::string& name, const std::vector<double>& means,
                           const std::vector<double>& errors);

/// InputError if two runs (files) start from the same packing (equal
/// fingerprints): averaging them would count one packing twice.
void require_distinct_packings(const std::vector<std::filesystem::path>& files,
                               const std::vector<std::uint64_t>& fingerprints);

/// Throws InputError unless the runs share γ̃, φ and N and start from
/// different packings (one run given twice, or a copy of it, would count one
/// packing twice and shrink the error).
PackingAverage average_over_packings(const std::vector<StoredRunSummary>& runs);

}  // namespace softglass::micro
