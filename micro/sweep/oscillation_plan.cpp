#include "micro/sweep/oscillation_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace softglass::micro {

namespace {

constexpr const char* kContext = "oscillation";

// A case's cost from the steady-shear model at its peak rate: each cycle
// shears 4γ0 of strain, at 2× the model's cost per strain (the model is the
// literal preset's; the default's friction against the neighbours costs
// more), and takes at least a few steps per sample (a cost per particle and
// sample taken from runs at N = 250 and γ0 = 1e-3). Below γ0 ≈ 0.03 a case
// is periodic after min_cycles; past yielding its cycles scatter and it runs
// towards max_cycles. Checked against measured runs in
// bench/results/oscillation-2026-11-26.md.
double case_cost(std::size_t particles, const OscillationProtocol& p, const std::string& scheme,
                 StokesReference stokes) {
  const double per_strain = 2.0 * rate_cost(particles, p.peak_gamma_tilde(), scheme, stokes) / 5.0;
  const double per_cycle = std::max(4.0 * p.amplitude * per_strain,
                                    p.samples_per_cycle * 5e-5 * static_cast<double>(particles));
  const double yielded = std::min(1.0, p.amplitude / 0.3);
  return per_cycle * (p.min_cycles + yielded * (p.max_cycles - p.min_cycles));
}

}  // namespace

OscillationPlan make_oscillation_plan(const OscillationSpec& spec) {
  OscillationPlan plan;
  plan.particles = spec.particles;
  plan.volume_fractions = spec.volume_fractions;
  plan.amplitudes = spec.amplitudes;
  plan.frequencies = spec.frequencies;
  require(plan.particles >= 2, "oscillation: needs at least 2 particles");
  require(!plan.amplitudes.empty() && !plan.frequencies.empty() && !plan.volume_fractions.empty(),
          "oscillation: 'amplitudes', 'frequencies' and the volume fractions must not be empty");
  require(spec.packings >= 1, "oscillation: 'packings' must be at least 1");
  require_sorted_unique(plan.volume_fractions, "volume fractions", kContext);
  require_sorted_unique(plan.amplitudes, "amplitudes", kContext);
  require_sorted_unique(plan.frequencies, "frequencies", kContext);
  for (double phi : plan.volume_fractions)
    require(phi >= 0.64 && phi <= 0.95,
            fmt::format("oscillation: volume fraction {} outside [0.64, 0.95]", phi));
  for (unsigned k = 0; k < spec.packings; ++k) plan.seeds.push_back(spec.first_seed + k);

  plan.directory = spec.directory;
  plan.table_csv = spec.directory / "oscillation.csv";
  plan.packing_table_csv = spec.directory / "oscillation_packings.csv";
  plan.table_h5 = spec.directory / "oscillation.h5";
  for (double phi : plan.volume_fractions)
    for (unsigned seed : plan.seeds)
      plan.packings.push_back(
          {phi, seed, spec.directory / "packings" / fmt::format("phi{:.4f}_seed{}.h5", phi, seed)});
  for (std::size_t p = 0; p < plan.packings.size(); ++p) {
    const SweepPacking& packing = plan.packings[p];
    for (double omega : plan.frequencies) {
      for (double gamma0 : plan.amplitudes) {
        OscillationProtocol protocol = spec.protocol;
        protocol.amplitude = gamma0;
        protocol.frequency = omega;
        try {
          protocol.validate();
        } catch (const InputError& e) {
          throw InputError(
              fmt::format("oscillation, gamma0 = {}, omega~ = {}: {}", gamma0, omega, e.what()));
        }
        plan.cases.push_back({p, packing.volume_fraction, gamma0, omega, packing.seed,
                              spec.directory / "runs" /
                                  fmt::format("phi{:.4f}_w{:.3e}_g{:.3e}_seed{}.h5",
                                              packing.volume_fraction, omega, gamma0, packing.seed),
                              case_cost(plan.particles, protocol, spec.scheme, spec.stokes),
                              protocol});
      }
    }
  }
  // File names print γ0 and ω̃ to four digits: two values closer than that
  // would share one file.
  for (std::size_t a = 0; a < plan.cases.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      require(plan.cases[a].file != plan.cases[b].file,
              fmt::format("oscillation: gamma0 = {}, omega~ = {} and gamma0 = {}, omega~ = {} "
                          "would share the result file {}; give values that differ in their "
                          "first four digits",
                          plan.cases[a].amplitude, plan.cases[a].frequency, plan.cases[b].amplitude,
                          plan.cases[b].frequency, plan.cases[a].file.string()));
  std::stable_sort(plan.cases.begin(), plan.cases.end(),
                   [](const OscillationCase& a, const OscillationCase& b) {
                     if (a.volume_fraction != b.volume_fraction)
                       return a.volume_fraction < b.volume_fraction;
                     if (a.frequency != b.frequency) return a.frequency < b.frequency;
                     if (a.amplitude != b.amplitude) return a.amplitude < b.amplitude;
                     return a.seed < b.seed;
                   });
  return plan;
}

}  // namespace softglass::micro
