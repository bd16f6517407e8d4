// Helpers shared by the micro tests: random configurations, an independent
// brute-force nearest-image search, a short sheared run, a per-test temporary
// directory.
//
// The brute-force search deliberately does NOT call LeesEdwardsBox::minimum_image:
// it enumerates the explicit Lees–Edwards images of particle j,
//     x_j + n_y (δ, L, 0) + n_x L e_x + n_z L e_z,
// and keeps the closest, so that tests comparing with it check the engine's
// image logic rather than reuse it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/h5_file.h"
#include "micro/analysis/shear_modulus.h"
#include "micro/contact/contact_law.h"
#include "micro/dynamics/integrator.h"
#include "micro/io/run_file.h"
#include "micro/packing/packing.h"
#include "micro/protocol/shear_run.h"
#include "micro/geometry/lees_edwards_box.h"
#include "micro/geometry/particles.h"

#include "tests/common/test_files.h"

namespace softglass::micro::testing {

/// A short sheared run of `packing` at γ̃ = 1e-4 with the engine's defaults
/// (EHD on, `euler`), exactly `strain` long.
struct ShortShear {
  ShearResult result;
  Particles final_particles;  // label order, wrapped
  LeesEdwardsBox final_box;
};
inline ShortShear shear_briefly(const Packing& packing, std::shared_ptr<const ContactLaw> law,
                                double skin, double strain, double check_interval = 1.0) {
  ShearModel model;
  model.gamma_tilde = 1e-4;
  OverdampedShear flow(ContactSystem(packing.particles, packing.box, std::move(law), skin), model);
  const auto integrator = make_integrator({.name = "euler"});
  ShearProtocol protocol;
  protocol.check_interval = check_interval;
  protocol.min_strain = protocol.max_strain = strain;
  protocol.min_stationary_strain =
      std::max(20 * protocol.sample_interval, std::min(1.0, strain / 2));
  // Braced initialisation runs left to right: the run first.
  return {run_shear(flow, *integrator, protocol), flow.system().wrapped_in_label_order(),
          flow.system().box()};
}

/// Makes the checkpoint file at `path` one of an older version, whose
/// /counters array held only its first `kept` entries.
inline void keep_older_counters(const std::filesystem::path& path, std::size_t kept) {
  H5File file = H5File::open_for_update(path);
  H5Group root = file.root();
  std::vector<double> counters = root.read_array("counters").data;
  counters.resize(kept);
  root.remove_child("counters");
  root.write("counters", counters);
  file.close();
}

/// The contact law called `name` (no table file).
/// The tests' small packing: N particles at φ, skin 0.3 (the neighbour grid
/// of a cell of 9–10 R), the default relaxation.
inline PackingSpec small_packing_spec(std::uint64_t seed, double phi = 0.8,
                                      std::size_t particles = 200) {
  PackingSpec spec;
  spec.particles = particles;
  spec.volume_fraction = phi;
  spec.skin = 0.3;
  spec.seed = seed;
  return spec;
}

inline std::shared_ptr<const ContactLaw> named_law(const std::string& name) {
  ContactLawSpec spec;
  spec.name = name;
  return make_contact_law(spec);
}

/// The run file's record of a fresh packing as `micro run` starts it: the
/// command, a parameter text naming N, the packing and its shear modulus.
inline RunRecord packing_record(const Packing& packing, std::shared_ptr<const ContactLaw> law,
                                double skin) {
  RunRecord record;
  record.command = "run";
  record.parameters =
      "subsection particles\n  set number = " + std::to_string(packing.particles.size()) +
      "\nend\n";
  record.packing = packing.report;
  record.packing_particles = packing.particles;
  record.packing_box = packing.box;
  ContactSystem system(packing.particles, packing.box, std::move(law), skin);
  record.modulus = shear_modulus(system);
  return record;
}

/// Uniformly random centres and Gaussian radii (mean 1, sd `polydispersity`,
/// cut at ±2.5 sd) in a cubic cell sized for volume fraction `phi`. Overlaps are
/// not avoided: this is the "random overlapping configuration" of the tests.
struct RandomConfiguration {
  std::vector<Vec3> position;
  std::vector<double> radius;
  double side = 0.0;
};

inline RandomConfiguration random_configuration(std::size_t n, double phi, std::uint64_t seed,
                                                double polydispersity = 0.1) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  RandomConfiguration c;
  double volume = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double z;
    do z = normal(rng);
    while (std::abs(z) > 2.5);
    c.radius.push_back(1.0 + polydispersity * z);
    volume += 4.0 / 3.0 * std::numbers::pi * std::pow(c.radius.back(), 3);
  }
  c.side = std::cbrt(volume / phi);
  std::uniform_real_distribution<double> uniform(0.0, c.side);
  for (std::size_t i = 0; i < n; ++i)
    c.position.emplace_back(uniform(rng), uniform(rng), uniform(rng));
  return c;
}

/// The Lees–Edwards image offset δ = (γ − ⌊γ⌋) L, computed here independently.
inline double offset_for(double side, double strain) {
  return (strain - std::floor(strain)) * side;
}

/// Nearest-image separation x_i − x_j by explicit enumeration of images.
inline Vec3 brute_force_separation(const Vec3& xi, const Vec3& xj, double side, double strain) {
  const double delta = offset_for(side, strain);
  Vec3 best = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (int ny = -1; ny <= 1; ++ny)
    for (int nx = -2; nx <= 2; ++nx)
      for (int nz = -1; nz <= 1; ++nz) {
        const Vec3 image = xj + Vec3(ny * delta + nx * side, ny * side, nz * side);
        const Vec3 d = xi - image;
        if (d.squaredNorm() < best.squaredNorm()) best = d;
      }
  return best;
}

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

/// Pairs (i < j) whose nearest-image distance is below R_i + R_j + extra.
/// Pairs within `margin` of that threshold are put in `ambiguous` instead, so
/// that comparisons are not decided by the last bit of a rounding.
inline PairSet brute_force_pairs(std::span<const Vec3> x, std::span<const double> radius,
                                 double side, double strain, double extra, double margin = 1e-9,
                                 PairSet* ambiguous = nullptr) {
  PairSet pairs;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t j = i + 1; j < x.size(); ++j) {
      const double r = brute_force_separation(x[i], x[j], side, strain).norm();
      const double cutoff = radius[i] + radius[j] + extra;
      if (std::abs(r - cutoff) < margin) {
        if (ambiguous) ambiguous->insert({i, j});
        continue;
      }
      if (r < cutoff) pairs.insert({i, j});
    }
  return pairs;
}

inline std::pair<std::uint32_t, std::uint32_t> ordered(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

using softglass::testing::read_text;
using softglass::testing::TemporaryDirectory;
using softglass::testing::write_text;

}  // namespace softglass::micro::testing
