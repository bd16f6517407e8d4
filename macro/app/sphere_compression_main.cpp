// sphere_compression: the large-deformation contact law of an incompressible
// neo-Hookean sphere between frictionless plates (macro/particle/
// sphere_compression.h), written as a `contact law = table` file of the
// particle model: rows (ε, F = f/(E* R_c²)) of the equivalent pair of spheres.
//
//   sphere_compression -o cases/contact_law_neohookean.dat
//
// The rows are --points plate displacements from --from to --to (δ/R),
// spaced geometrically.
// Each row printed: δ/R, ε, F, F over Hertz's (4/3) ε^{3/2}, the contact
// radius a/R, the largest |J − 1|, Newton iterations, and the energy identity
// (ΔΠ/Δδ against the mean plate force of the step, relative).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "common/atomic_output.h"
#include "common/command_line.h"
#include "common/errors.h"
#include "common/version.h"
#include "macro/particle/sphere_compression.h"

using namespace softglass;
using namespace softglass::macro::particle;

int main(int argc, char** argv) {
  CLI::App app{"sphere_compression: the contact law of a neo-Hookean sphere, by finite elements"};
  SphereCompressionSettings settings;
  double from = 6.25e-4, to = 0.25;
  unsigned int points = 40;
  std::string output;
  bool force = false;
  app.add_option("--refinements", settings.global_refinements, "uniform refinements (1 to 7)")
      ->capture_default_str();
  app.add_option("--pole-refinements", settings.pole_refinements,
                 "refinements graded towards the contact (0 to 12)")
      ->capture_default_str();
  app.add_option("--poisson", settings.poisson_ratio, "Poisson's ratio (0 to 1/2)")
      ->capture_default_str();
  app.add_option("--penalty", settings.penalty, "the plate's penalty stiffness, E*/R")
      ->check(positive)
      ->capture_default_str();
  app.add_option("--from", from, "first plate displacement delta/R")
      ->check(positive)
      ->capture_default_str();
  app.add_option("--to", to, "last plate displacement delta/R (< 1/2)")
      ->check(positive)
      ->capture_default_str();
  app.add_option("--points", points, "rows of the table (>= 2)")->capture_default_str();
  app.add_option("-o,--output", output, "the table file to write (contact law = table)");
  app.add_flag("-f,--force", force, "overwrite the output file");
  app.set_version_flag("--version",
                       fmt::format("softglass sphere_compression {} ({})", kVersion, kGitRevision));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_command_line_error("sphere_compression", app, e);
  }

  return run_reporting_errors("sphere_compression", [&] {
    require(points >= 2, fmt::format("--points {} is not allowed; allowed: 2 or more", points));
    require(from < to && to < 0.5,
            fmt::format("--from {} and --to {} are not allowed; allowed: 0 < from < to < 1/2", from,
                        to));
    std::unique_ptr<AtomicOutput> file;
    if (!output.empty()) file = std::make_unique<AtomicOutput>(output, force);

    SphereCompression sphere(settings);
    fmt::print("# {} cells, {} unknowns; nu = {}, penalty {} E*/R\n", sphere.n_cells(),
               sphere.n_dofs(), settings.poisson_ratio, settings.penalty);
    fmt::print("# delta/R  eps  F  F/Hertz  a/R  max|J-1|  newton  energy_identity\n");
    std::vector<CompressionState> states;
    double last = 0.0, last_energy = 0.0, last_force = 0.0;
    for (unsigned int i = 0; i < points; ++i) {
      const double delta = from * std::pow(to / from, double(i) / (points - 1));
      const CompressionState s = sphere.compress_to(delta);
      const double eps = pair_deformation(s), f = pair_force(s);
      // ΔΠ = ∫ f dδ over the step, f taken as the power law through its ends
      // (from δ = 0, Hertz's exponent): the relative difference is what
      // the force and the energy disagree by, up to that interpolation.
      const double exponent =
          last > 0.0 ? std::log(s.force / last_force) / std::log(delta / last) : 1.5;
      const double identity =
          (s.energy - last_energy) / ((s.force * delta - last_force * last) / (exponent + 1.0)) -
          1.0;
      fmt::print("{:.5e} {:.5e} {:.6e} {:.4f} {:.4f} {:.1e} {} {:+.2e}\n", delta, eps, f,
                 f / (4.0 / 3.0 * std::pow(eps, 1.5)), s.contact_radius, s.volume_change,
                 s.newton_iterations, identity);
      states.push_back(s);
      last = delta;
      last_energy = s.energy;
      last_force = s.force;
    }
    if (file) {
      file->write_and_commit([&](std::ostream& out) {
        out << "# The contact law of an elastic sphere computed by finite elements, for\n"
               "# `contact law = table`: eps = h/R_c, F = f/(E* R_c^2) of two equal spheres,\n"
               "# from one sphere pressed between frictionless plates (eps = 4 delta/R,\n"
               "# F = 4 f/(E* R^2); macro/particle/sphere_compression.h). Neo-Hookean,\n";
        out << fmt::format(
            "# Poisson's ratio {}, {} cells, {} unknowns, penalty {} E*/R.\n"
            "# Written by softglass sphere_compression {} ({}):\n#  ",
            settings.poisson_ratio, sphere.n_cells(), sphere.n_dofs(), settings.penalty, kVersion,
            kGitRevision);
        for (int i = 0; i < argc; ++i) out << ' ' << argv[i];
        out << "\n# eps F\n";
        for (const CompressionState& s : states)
          out << fmt::format("{:.6e} {:.6e}\n", pair_deformation(s), pair_force(s));
      });
    }
    return 0;
  });
}
