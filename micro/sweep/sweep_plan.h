// What a sweep runs: the state points (φ, γ̃) × packings (seeds), the packings
// they share and where every result goes.
//
// A sweep is a list of independent cases. The packing of a (φ, seed) is made
// once and sheared at every γ̃ (as in the paper), so a sweep has two phases:
// the packings, then the cases. Every file is written atomically, so a file that
// exists is complete: a rerun skips it, which makes an interrupted sweep
// resumable and lets any number of workers (threads, MPI ranks, array jobs)
// share one output folder as long as they split the work.
//
// Every (φ, seed) may also have a quasi-static case (γ̃ = 0, athermal
// quasi-static shear from the same packing: protocol/quasi_static_run.h), the
// low end of the flow curve; it is on by default.
//
// Fidelity presets fix N, the state points, the number of packings and the
// accuracy of each run; docs/sweeps.md gives their measured error and cost.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "micro/model/stokes_friction.h"
#include "micro/protocol/aqs.h"

namespace softglass::micro {

/// How long each run of a preset shears: the stopping rule of
/// protocol/shear_run.h (subsection `shear` of a run file).
struct RunLength {
  double target_relative_error;  // of σ, N1 and N2
  double min_strain, max_strain;
  double min_stationary_strain;  // the averaging window after the transient, at least
};

struct SweepPreset {
  std::string name;
  std::size_t particles;
  std::vector<double> volume_fractions;
  std::vector<double> gamma_tildes;
  unsigned packings;
  RunLength run;
  std::string description;  // what it is for
};

/// fast, standard, paper.
const std::vector<SweepPreset>& sweep_presets();
const SweepPreset& sweep_preset(const std::string& name);  // InputError if unknown

/// The `sweep` subsection of a sweep file. Empty lists and zero counts take
/// the preset's values; `custom` has none and needs them all.
struct SweepSpec {
  std::string preset = "standard";
  std::vector<double> volume_fractions{};  // {}: lets tests name single fields
  std::vector<double> gamma_tildes{};
  unsigned packings = 0;
  unsigned first_seed = 1;
  std::size_t particles = 0;
  std::filesystem::path directory = "sweep";
  std::size_t checkpoint_steps = 20000;  // accepted steps between checkpoints (0: none)
  bool quasi_static = true;              // a quasi-static case per (φ, seed)
  double quasi_static_strain_step = kDefaultAqsStrainStep;
  double quasi_static_force_tolerance = AqsSettings{}.relative_force;  // residual / mean force
  // The runs' integrator and what their Stokes friction acts against (which
  // `auto` resolves by): only the cost estimates use them.
  std::string scheme = "auto";
  StokesReference stokes = StokesReference::affine;
};

struct SweepPacking {
  double volume_fraction;
  unsigned seed;
  std::filesystem::path file;  // `micro pack` record
};

struct SweepCase {
  std::size_t packing;                  // index into SweepPlan::packings
  double volume_fraction, gamma_tilde;  // γ̃ = 0 for the quasi-static case
  unsigned seed;
  std::filesystem::path file;  // `micro run` record
  double cost;  // estimate (≈ s per 5 strain on this machine): order, split, time left
  bool quasi_static = false;
};

struct SweepPlan {
  std::size_t particles;
  std::optional<RunLength> run;  // the preset's; none for custom (the file's `shear`)
  std::vector<double> volume_fractions, gamma_tildes;  // sorted; γ̃ of the rate cases only
  std::vector<unsigned> seeds;
  bool quasi_static;  // the cases include one quasi-static case per packing
  double quasi_static_strain_step;
  double quasi_static_force_tolerance;
  std::vector<SweepPacking> packings;
  std::vector<SweepCase> cases;  // by φ, then γ̃ (quasi-static first), then seed
  std::filesystem::path directory, table_csv, packing_table_csv, table_h5;
};

// Cost estimates of the cases, in seconds of one core per 5 strain: each
// scheme's own (IntegratorTraits), growing like N for the explicit scheme and
// like N^1.35 for the minimisers (docs/sweeps.md measures it). The estimates
// order the work, split it over the workers (longest first) and apportion the
// time left, so a factor 2 is harmless; a wrong scheme (an explicit estimate
// for an implicit run) is not.
/// The size factor of the minimisers, (N/1000)^1.35.
double minimiser_scale(std::size_t particles);
/// A case of N particles sheared at γ̃ `rate` by `scheme` (`auto` resolved
/// here, by `stokes`).
double rate_cost(std::size_t particles, double rate, const std::string& scheme,
                 StokesReference stokes);

/// Sorts `values` and throws InputError "<context>: '<entry>' lists x twice"
/// for two values equal to 1e-9.
void require_sorted_unique(std::vector<double>& values, const char* entry, const char* context);

/// Resolves the preset, checks the lists (φ in [0.64, 0.95], γ̃ in
/// [1e-14, 0.1], no duplicates) and the quasi-static strain step (in
/// (0, 0.01]), and names every file. Throws InputError naming the entry.
SweepPlan make_sweep_plan(const SweepSpec& spec);

}  // namespace softglass::micro
