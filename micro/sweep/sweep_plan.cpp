#include "micro/sweep/sweep_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "common/errors.h"
#include "micro/dynamics/integrator.h"

namespace softglass::micro {

namespace {

// γ̃ from 10^first to 10^last at `per_decade` points per decade.
std::vector<double> decades(int first, int last, int per_decade) {
  std::vector<double> rates;
  for (int k = first * per_decade; k <= last * per_decade; ++k)
    rates.push_back(std::pow(10.0, static_cast<double>(k) / per_decade));
  return rates;
}

const std::vector<double> kPaperVolumeFractions = {0.70, 0.75, 0.80, 0.85, 0.90};

// The quasi-static case's cost (rate_cost's units): the mean over the
// quasi-static cases of the whole `paper` sweep at Δγ = 1e-3 (it falls with
// φ; the same sweep as the `bdf2` traits), ∝ Δγ^-0.42 from those cases' cost
// at 1e-3 against 2e-4 (bench/results/sweep_cost_model-2026-11-30.md,
// aqs_strain_step-2026-11-29.md).
double quasi_static_cost(std::size_t particles, double strain_step) {
  return 52.0 * minimiser_scale(particles) * std::pow(strain_step / 1e-3, -0.42);
}

}  // namespace

double minimiser_scale(std::size_t particles) {
  return std::pow(static_cast<double>(particles) / 1000.0, 1.35);
}

double rate_cost(std::size_t particles, double rate, const std::string& scheme,
                 StokesReference stokes) {
  const IntegratorSpec resolved = IntegratorSpec{.name = scheme}.resolved_for(rate, stokes);
  const IntegratorTraits& t = integrators().at(resolved.name).traits;
  const double size =
      t.minimises ? minimiser_scale(particles) : static_cast<double>(particles) / 1000.0;
  return size *
         std::max(t.floor_seconds, t.seconds_at_reference * std::pow(rate / 1e-5, t.rate_exponent));
}

void require_sorted_unique(std::vector<double>& values, const char* entry, const char* context) {
  std::sort(values.begin(), values.end());
  const auto twin = std::adjacent_find(values.begin(), values.end(), [](double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::abs(b);
  });
  if (twin != values.end())
    throw InputError(fmt::format("{}: '{}' lists {} twice", context, entry, *twin));
}

const std::vector<SweepPreset>& sweep_presets() {
  // Run lengths: fast and standard shear until σ, N1 and N2 are known to the
  // target (or up to max strain); paper follows the paper's protocol, "until
  // steady state was reached, then averaging over several strain units" with
  // five packings: 5 strain, the transient cut by MSER, at least 3 averaged.
  static const std::vector<SweepPreset> presets = {
      {"fast",
       250,
       {0.70, 0.80, 0.90},
       decades(-6, -4, 2),
       1,
       {.target_relative_error = 0.10,
        .min_strain = 5,
        .max_strain = 20,
        .min_stationary_strain = 5},
       "a first look: three volume fractions, one small packing each"},
      {"standard",
       1000,
       kPaperVolumeFractions,
       decades(-7, -4, 1),
       3,
       {.target_relative_error = 0.05,
        .min_strain = 5,
        .max_strain = 50,
        .min_stationary_strain = 5},
       "the paper's volume fractions at one rate per decade, three packings"},
      {"paper",
       1000,
       kPaperVolumeFractions,
       decades(-9, -4, 2),
       5,
       {.target_relative_error = 0.05,
        .min_strain = 5,
        .max_strain = 5,
        .min_stationary_strain = 3},
       "the paper's protocol: N = 1000, five packings, two rates per decade down to 1e-9, 5 strain "
       "per run"},
  };
  return presets;
}

const SweepPreset& sweep_preset(const std::string& name) {
  for (const auto& preset : sweep_presets())
    if (preset.name == name) return preset;
  throw InputError(
      fmt::format("sweep: unknown preset '{}' (fast, standard, paper or custom)", name));
}

SweepPlan make_sweep_plan(const SweepSpec& spec) {
  const bool custom = spec.preset == "custom";
  const SweepPreset fallback{"custom", 0, {}, {}, 0, {}, ""};
  const SweepPreset& preset = custom ? fallback : sweep_preset(spec.preset);

  SweepPlan plan;
  plan.particles = spec.particles ? spec.particles : preset.particles;
  plan.volume_fractions =
      spec.volume_fractions.empty() ? preset.volume_fractions : spec.volume_fractions;
  plan.gamma_tildes = spec.gamma_tildes.empty() ? preset.gamma_tildes : spec.gamma_tildes;
  const unsigned packings = spec.packings ? spec.packings : preset.packings;
  if (!custom) plan.run = preset.run;
  if (plan.particles == 0 || plan.volume_fractions.empty() || plan.gamma_tildes.empty() ||
      packings == 0)
    throw InputError(
        "sweep: preset 'custom' needs 'particles', 'volume fractions', 'gamma dot tildes' and "
        "'packings' in subsection 'sweep'");

  require_sorted_unique(plan.volume_fractions, "volume fractions", "sweep");
  require_sorted_unique(plan.gamma_tildes, "gamma dot tildes", "sweep");
  for (double phi : plan.volume_fractions)
    if (!(phi >= 0.64 && phi <= 0.95))
      throw InputError(fmt::format("sweep: volume fraction {} outside [0.64, 0.95]", phi));
  for (double rate : plan.gamma_tildes)
    if (!(rate >= 1e-14 && rate <= 0.1))
      throw InputError(fmt::format("sweep: gamma dot tilde {} outside [1e-14, 0.1]", rate));
  for (unsigned k = 0; k < packings; ++k) plan.seeds.push_back(spec.first_seed + k);
  plan.quasi_static = spec.quasi_static;
  // The quasi-static settings, each in (0, largest] (NaN refused).
  const auto quasi_static_setting = [](double value, const char* name, double largest) {
    if (!(value > 0 && value <= largest))
      throw InputError(
          fmt::format("sweep: '{}' = {}; allowed: (0, {}]", name, value, largest));
    return value;
  };
  plan.quasi_static_strain_step = quasi_static_setting(
      spec.quasi_static_strain_step, "quasi-static strain step", kMaxAqsStrainStep);
  plan.quasi_static_force_tolerance = quasi_static_setting(
      spec.quasi_static_force_tolerance, "quasi-static force tolerance", kMaxAqsForceTolerance);

  plan.directory = spec.directory;
  plan.table_csv = spec.directory / "flow_curve.csv";
  plan.packing_table_csv = spec.directory / "flow_curve_packings.csv";
  plan.table_h5 = spec.directory / "flow_curve.h5";
  for (double phi : plan.volume_fractions) {
    for (unsigned seed : plan.seeds) {
      plan.packings.push_back(
          {phi, seed, spec.directory / "packings" / fmt::format("phi{:.4f}_seed{}.h5", phi, seed)});
    }
  }
  for (std::size_t p = 0; p < plan.packings.size(); ++p) {
    const SweepPacking& packing = plan.packings[p];
    for (double rate : plan.gamma_tildes) {
      plan.cases.push_back({p, packing.volume_fraction, rate, packing.seed,
                            spec.directory / "runs" /
                                fmt::format("phi{:.4f}_gt{:.3e}_seed{}.h5", packing.volume_fraction,
                                            rate, packing.seed),
                            rate_cost(plan.particles, rate, spec.scheme, spec.stokes)});
    }
    if (plan.quasi_static) {
      plan.cases.push_back(
          {p, packing.volume_fraction, 0.0, packing.seed,
           spec.directory / "runs" /
               fmt::format("phi{:.4f}_aqs_seed{}.h5", packing.volume_fraction, packing.seed),
           quasi_static_cost(plan.particles, plan.quasi_static_strain_step), true});
    }
  }
  std::stable_sort(plan.cases.begin(), plan.cases.end(),
                   [](const SweepCase& a, const SweepCase& b) {
                     if (a.volume_fraction != b.volume_fraction)
                       return a.volume_fraction < b.volume_fraction;
                     if (a.gamma_tilde != b.gamma_tilde) return a.gamma_tilde < b.gamma_tilde;
                     return a.seed < b.seed;
                   });
  return plan;
}

}  // namespace softglass::micro
