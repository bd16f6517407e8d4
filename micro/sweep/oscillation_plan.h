// What `micro oscillate` runs: amplitude and frequency sweeps of oscillatory
// shear (protocol/oscillatory_run.h) over volume fractions and packings, laid
// out like a flow-curve sweep (sweep_plan.h): the packings of each (φ, seed)
// first, then one case per (φ, seed, γ0, ω̃), each written whole so that a
// rerun skips what exists, then the table.
#pragma once

#include <filesystem>
#include <vector>

#include "micro/protocol/oscillatory_run.h"
#include "micro/sweep/sweep_plan.h"

namespace softglass::micro {

/// The `oscillation` subsection of an oscillation file.
struct OscillationSpec {
  std::vector<double> amplitudes{0.01};    // γ0
  std::vector<double> frequencies{1e-7};   // ω̃
  std::vector<double> volume_fractions{};  // empty: the file's particles/volume fraction
  unsigned packings = 1;
  unsigned first_seed = 1;
  std::size_t particles = 0;     // the file's particles/number (set by the reader)
  OscillationProtocol protocol;  // amplitude and frequency: per case
  std::filesystem::path directory = "oscillation";
  std::size_t checkpoint_steps = 20000;
  // The runs' integrator and what their Stokes friction acts against (which
  // `auto` resolves by): only the cost estimates use them.
  std::string scheme = "auto";
  StokesReference stokes = StokesReference::affine;
};

struct OscillationCase {
  std::size_t packing;  // index into OscillationPlan::packings
  double volume_fraction, amplitude, frequency;
  unsigned seed;
  std::filesystem::path file;  // the run's record
  double cost;                 // estimate, seconds of one core: order, split, time left
  /// The case's protocol (the spec's, at this amplitude and frequency).
  OscillationProtocol protocol;
};

struct OscillationPlan {
  std::size_t particles;
  std::vector<double> volume_fractions, amplitudes, frequencies;  // sorted
  std::vector<unsigned> seeds;
  std::vector<SweepPacking> packings;
  std::vector<OscillationCase> cases;  // by φ, ω̃, γ0, seed
  std::filesystem::path directory, table_csv, packing_table_csv, table_h5;
};

/// Checks the lists (each value once; γ0, ω̃ and their product in the
/// protocol's ranges; φ in [0.64, 0.95]) and names every file. Throws
/// InputError naming the entry.
OscillationPlan make_oscillation_plan(const OscillationSpec& spec);

}  // namespace softglass::micro
