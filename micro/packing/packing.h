// Compressed, force-balanced packings of polydisperse soft spheres (docs/physics.md, "Protocol").
//
// Protocol: radii drawn from the distribution (mean 1), centres placed uniformly
// at random in a cell at a low volume fraction φ₀, then the cell is compressed
// in steps of Δφ, each followed by a FIRE relaxation that stops at a loose
// residual or after `stage_iterations` (the compression rate: near jamming,
// φ_J ≈ 0.64, relaxation slows down critically and a full relaxation of every
// stage would cost 10⁵ iterations for nothing), and the packing at the target φ
// is relaxed to force balance to a tight residual. Every random number comes
// from `seed`.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>

#include "micro/packing/fire.h"
#include "micro/model/contact_system.h"
#include "micro/geometry/radius_distribution.h"

namespace softglass::micro {

struct PackingSpec {
  std::size_t particles = 1000;
  double volume_fraction = 0.80;
  RadiusDistribution radii;
  std::uint64_t seed = 1;
  double initial_volume_fraction = 0.50;
  double compression_step = 0.01;       // Δφ between relaxations
  double stage_tolerance = 1e-3;        // FIRE residual between compression steps
  std::size_t stage_iterations = 2000;  // FIRE budget per intermediate step
  FireSettings relaxation;              // final relaxation
  double skin = 0.6;                    // neighbour-list skin, units of R

  void validate() const;
};

/// What users check on a packing.
struct PackingReport {
  std::size_t particles = 0;
  double volume_fraction = 0.0;
  double side = 0.0;          // cell side, units of R
  double coordination = 0.0;  // Z = 2 × contacts / N
  double coordination_nonrattler = 0.0;
  std::size_t rattlers = 0;       // particles with < 4 contacts, removed iteratively
  double mean_deformation = 0.0;  // ⟨ε⟩ over contacts
  double max_deformation = 0.0;
  double pressure = 0.0;             // Π = −tr σ^e / 3, units of E*
  double energy_per_particle = 0.0;  // units of E* R³
  double residual = 0.0;             // max|F| / ⟨|f_c|⟩
  std::size_t iterations = 0;        // FIRE iterations over all stages
  bool converged = false;
  double seconds = 0.0;
};

/// Measures a relaxed system (forces are recomputed).
PackingReport describe_packing(ContactSystem& system);

struct Packing {
  Particles particles;  // in label order
  LeesEdwardsBox box;
  PackingReport report;
};

/// From the system at spec.initial_volume_fraction, compresses it stage by
/// stage to spec.volume_fraction (of the cell, or of the slab between its
/// walls) and relaxes it to force balance; returns the FIRE iterations.
std::size_t compress(ContactSystem& system, const PackingSpec& spec,
                     const std::function<void(double)>& progress);
/// The report of a compressed system: describe_packing with the protocol's
/// iterations, convergence and time since `start`.
PackingReport finish_report(ContactSystem& system, const PackingSpec& spec, std::size_t iterations,
                            std::chrono::steady_clock::time_point start);

/// `progress(φ)` is called after every compression stage, if given.
Packing make_packing(const PackingSpec& spec, std::shared_ptr<const ContactLaw> law,
                     const std::function<void(double)>& progress = {});

}  // namespace softglass::micro
