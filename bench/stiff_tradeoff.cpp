// stiff_tradeoff: cost and accuracy of the integrators across γ̃ (issue 4).
//
// One packing, then each requested run from it: a scheme and tolerance
// (`--run euler:1e-4`, `--run implicit:1e-3`, …), optionally a third number —
// the fraction of the stability limit for `euler` (`euler:1e-5:0.4`), the
// largest step in strain for `implicit` and `bdf2` (`implicit:1e-3:5e-4`) — or
// quasi-static shear (`--run aqs:2e-4`, the number being the strain step;
// `aqs:2e-4:1e-5` also sets the minimiser's force tolerance), over the same
// strain window [0, --strain]. Each prints one line
//   run <scheme> <tol> gamma <γ̃> sigma <σ> N1 <N1> N2 <N2> seconds <s>
//       per_strain <s/strain> steps <n> rejected <n> strain <done> complete <0|1>
// where σ, N1, N2 are means of the total stress over samples every 0.01 strain
// (units of E*). A run that exceeds --time-limit seconds stops early: its cost
// per strain is extrapolated from the strain it did and its stresses are not
// comparable (complete 0). bench/stiff_tradeoff.sh turns this into the table.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.h"
#include "micro/protocol/aqs.h"
#include "micro/dynamics/integrator.h"
#include "micro/packing/packing.h"

using namespace softglass::micro;
using softglass::InputError;

int run_all(const PackingSpec& spec, double gamma_tilde, double strain, double time_limit,
            double sample, double preshear, const std::vector<std::string>& runs);

int main(int argc, char** argv) {
  CLI::App app{"stiff_tradeoff: integrator cost and accuracy at one shear rate"};
  PackingSpec spec;
  spec.particles = 256;
  double gamma_tilde = 1e-5, strain = 0.2, time_limit = 600.0, sample = 0.01, preshear = 0.0;
  std::vector<std::string> runs;
  app.add_option("--particles", spec.particles);
  app.add_option("--phi", spec.volume_fraction);
  app.add_option("--seed", spec.seed);
  app.add_option("--gamma-tilde", gamma_tilde);
  app.add_option("--strain", strain, "strain window of every run");
  app.add_option("--preshear", preshear,
                 "strain of quasi-static shear (AQS, step 1e-3) applied to the packing first");
  app.add_option("--time-limit", time_limit, "seconds per run before it is cut short");
  app.add_option("--run", runs,
                 "scheme:tolerance[:stability fraction (euler) | max step (implicit, bdf2)] or "
                 "aqs:strain_step[:force tolerance]")
      ->required();
  CLI11_PARSE(app, argc, argv);
  return softglass::run_reporting_errors("stiff_tradeoff", [&] {
    return run_all(spec, gamma_tilde, strain, time_limit, sample, preshear, runs);
  });
}

// A --run value's number, or an InputError naming it.
double run_number(const std::string& run, const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v) && v > 0) return v;
  } catch (const std::logic_error&) {
  }
  throw InputError("--run " + run + ": '" + text + "' is not a positive number");
}

int run_all(const PackingSpec& spec, double gamma_tilde, double strain, double time_limit,
            double sample, double preshear, const std::vector<std::string>& runs) {
  std::shared_ptr<const ContactLaw> law = make_contact_law({});
  Packing packing = make_packing(spec, law);
  if (preshear > 0) {
    // A sheared (steady-state-like) start, the same for every run.
    ContactSystem system(packing.particles, packing.box, law, spec.skin);
    AqsSettings s;
    s.strain_step = 1e-3;
    s.strain = preshear;
    s.min_stationary_strain = preshear / 2;
    run_aqs(system, s);
    packing.particles = system.wrapped_in_label_order();
    packing.particles.velocity.assign(packing.particles.size(), Vec3::Zero());
    packing.box = system.box();
  }
  fmt::print("particles {} phi {} seed {} gamma {:.0e} strain {} preshear {}\n", spec.particles,
             spec.volume_fraction, spec.seed, gamma_tilde, strain, preshear);
  std::fflush(stdout);

  for (const std::string& run : runs) {
    // scheme:value[:third]
    std::vector<std::string> parts;
    for (std::size_t from = 0;;) {
      const auto colon = run.find(':', from);
      parts.push_back(run.substr(from, colon - from));
      if (colon == std::string::npos) break;
      from = colon + 1;
    }
    const std::string scheme = parts[0];
    const double value = parts.size() > 1 ? run_number(run, parts[1]) : 0.0;
    // euler: the third number is the stability fraction; implicit, bdf2: the
    // max step; aqs: the force tolerance.
    const bool implicit = scheme != "euler";
    const double third = parts.size() > 2   ? run_number(run, parts[2])
                         : scheme == "aqs" ? AqsSettings{}.relative_force
                         : implicit        ? IntegratorSpec{}.max_step
                                           : IntegratorSpec{}.stability_fraction;
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    double sigma = 0, n1 = 0, n2 = 0, done = 0;
    std::size_t samples = 0, steps = 0, rejected = 0, newton = 0, linear = 0;
    bool complete = true;
    try {
      if (scheme == "aqs") {
        AqsSettings s;
        s.strain_step = value;
        s.relative_force = third;
        s.strain = strain;
        s.min_stationary_strain = strain / 2;
        ContactSystem system(packing.particles, packing.box, law, spec.skin);
        const AqsResult r = run_aqs(system, s);
        // Samples at the same strains as the dynamic runs.
        const auto every = static_cast<std::size_t>(std::llround(sample / value));
        for (std::size_t k = every - 1; k < r.series.size(); k += every) {
          const ShearObservables o = observables(r.series.elastic[k]);
          sigma += o.shear, n1 += o.n1, n2 += o.n2, ++samples;
        }
        steps = r.steps;
        newton = r.minimiser.iterations;
        linear = r.minimiser.cg_iterations;
        done = strain;
      } else {
        ShearModel model;
        model.gamma_tilde = gamma_tilde;
        OverdampedShear flow(ContactSystem(packing.particles, packing.box, law, spec.skin), model);
        IntegratorSpec ispec;
        ispec.name = scheme;
        ispec.tolerance = value;
        (implicit ? ispec.max_step : ispec.stability_fraction) = third;
        const auto integrator = make_integrator(ispec);
        const double origin = flow.strain();
        double next = origin + sample;
        flow.sample_stress_from(next - 1e-9 * sample);
        while (flow.strain() - origin < strain - 1e-9 * sample) {
          integrator->step(flow, next - flow.strain());
          if (flow.strain() >= next - 1e-9 * sample) {
            const ShearObservables o = observables(flow.stress().total());
            sigma += o.shear, n1 += o.n1, n2 += o.n2, ++samples;
            next += sample;
            flow.sample_stress_from(next - 1e-9 * sample);
          }
          if (elapsed() > time_limit) {
            complete = false;
            break;
          }
        }
        done = flow.strain() - origin;
        steps = integrator->stats().accepted;
        rejected = integrator->stats().rejected;
        newton = integrator->stats().minimiser.iterations;
        linear = integrator->stats().minimiser.cg_iterations;
      }
    } catch (const std::exception& e) {
      fmt::print("run {} {:.0e}:{} failed \"{}\"\n", scheme, value, third, e.what());
      std::fflush(stdout);
      continue;
    }
    const double seconds = elapsed();
    const double k = samples > 0 ? 1.0 / double(samples) : 0.0;
    fmt::print(
        "run {} {:.0e}:{} gamma {:.0e} sigma {:.6e} N1 {:.6e} N2 {:.6e} seconds {:.2f} per_strain "
        "{:.4g} steps {} rejected {} newton {} cg {} strain {:.4f} complete {}\n",
        scheme, value, third, gamma_tilde, sigma * k, n1 * k, n2 * k, seconds,
        seconds / std::max(done, 1e-12), steps, rejected, newton, linear, done, complete ? 1 : 0);
    std::fflush(stdout);
  }
  return 0;
}
