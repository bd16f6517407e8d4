#include "micro/app/slip_command.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/atomic_output.h"
#include "common/errors.h"
#include "common/h5_file.h"
#include "common/output_folder.h"
#include "micro/analysis/plug_slip.h"
#include "micro/input/parameter_file.h"
#include "micro/packing/wall_packing.h"

namespace softglass::micro {

namespace {

// The row of slip.csv for one run (its own CSV keeps it for reruns).
std::string summary_row(double phi, double rate, unsigned seed, double gap,
                        const WallRunSummary& s) {
  std::string row = fmt::format("{},{:g},{},{:.6g},{},{}", phi, rate, seed, gap,
                                s.stationary_samples, s.converged ? 1 : 0);
  for (const ObservableEstimate& e : s.estimates)
    row += fmt::format(",{:.8g},{:.3g}", e.estimate.mean, e.estimate.standard_error);
  return row;
}

std::string summary_header() {
  std::string header = "phi,gamma_app,seed,gap,stationary_samples,converged";
  for (const std::string& name : wall_observable_names())
    header += fmt::format(",{0},{0}_se", name);
  return header;
}

void write_run(const std::filesystem::path& h5, const WallRunResult& run,
               const WallRunSummary& summary, const Walls& walls, const std::string& parameters) {
  AtomicOutput out(h5, true);
  H5File file = H5File::create(out.temporary_path());
  H5Group root = file.root();
  root.write_string("parameters", parameters);
  root.write_scalar("gap", walls.gap());
  root.write("strain", run.strain);
  H5Group series = root.create_group("series");
  H5Group means = root.create_group("stationary");
  for (const std::string& name : wall_observable_names()) {
    series.write(name, wall_observable_series(run, name));
    const MeanEstimate& e = find_estimate(summary.estimates, name);
    means.write(name, std::vector<double>{e.mean, e.standard_error});
  }
  means.set_attribute("transient_samples", static_cast<std::int64_t>(summary.transient_samples));
  H5Group profile = root.create_group("profile");
  const std::size_t bins = summary.profile.size();
  std::vector<double> centre(bins);
  for (std::size_t b = 0; b < bins; ++b)
    centre[b] = (static_cast<double>(b) + 0.5) / static_cast<double>(bins);
  profile.write("y_over_gap", centre);
  profile.write("u_x", summary.profile);
  profile.write("u_x_se", summary.profile_error);
  file.close();
  out.commit();
}

// What a run's result depends on: the model and packing (the parameter file
// without its walls subsection) and the walls' run settings — not the list of
// rates, packings or the output folder, which only say which runs there are.
std::string run_identity(const SlipParameters& prm) {
  const SlipSpec& s = prm.spec;
  return prm.base.text +
         fmt::format("# walls: strain {}, sample interval {}, central fraction {}, profile bins "
                     "{}, solvent flow {}\n",
                     s.run.strain, s.run.sample_interval, s.run.sampling.central_fraction,
                     s.run.sampling.bins, to_string(s.solvent));
}

// Rows of plug_slip.csv for one packing: the plug's σ_w at slip speeds
// U = V η_s/(E* R) from 1e-13 to 1e-2, eight per decade (analysis/plug_slip.h).
std::vector<std::string> plug_rows(double phi, unsigned seed, const PlugSlipLaw& law) {
  std::vector<std::string> rows;
  for (int i = -13 * 8; i <= -2 * 8; ++i) {
    const double u = std::pow(10.0, i / 8.0);
    rows.push_back(fmt::format("{},{},{:.6e},{:.8e}", phi, seed, u, law.wall_stress(u)));
  }
  return rows;
}

// The law of the packing's wall contacts at rest.
PlugSlipLaw plug_law(const WallPacking& walls, std::shared_ptr<const ContactLaw> law, double skin,
                     double rest_thickness) {
  ContactSystem system(walls.packing.particles, walls.packing.box, std::move(law), skin);
  system.set_walls(walls.walls);
  const double side = walls.packing.box.side();
  return PlugSlipLaw(system.compute_forces().walls, side * side, rest_thickness);
}

}  // namespace

void slip_command(const CommandOptions& options) {
  set_interruption_notice(
      "micro slip: interrupted; run the same command again to resume (finished runs are kept)");
  const SlipParameters prm = read_slip_file(options.parameter_file);
  const SlipSpec& spec = prm.spec;
  const IntegratorSpec scheme = [&] {
    IntegratorSpec s = prm.base.integrator;
    if (s.name == "auto") s.name = "euler";  // the implicit step has no wall films yet
    require(s.name == "euler", fmt::format("walls: integrator/scheme = {} does not carry the wall "
                                           "films; use euler (or auto)",
                                           s.name));
    return s.resolved_for(spec.apparent_rates.front(), prm.base.shear_model.drag.stokes.reference);
  }();
  // Before the first packing: a folder that cannot take the results is
  // refused at once.
  const OutputFolder folder(spec.directory);
  const std::filesystem::path runs = spec.directory / "runs";
  const std::string identity = run_identity(prm);
  const auto law = std::shared_ptr<const ContactLaw>(make_contact_law(prm.base.contact_law));
  std::vector<std::string> rows, plug;
  for (unsigned k = 0; k < spec.packings; ++k) {
    PackingSpec packing = prm.base.packing;
    packing.seed = spec.first_seed + k;
    const WallPacking walls = make_wall_packing(packing, law);
    if (!options.quiet)
      std::cout << fmt::format("packing seed {}: N = {}, phi = {}, gap H = {:.3f} R, side {:.3f} R\n",
                               packing.seed, packing.particles, packing.volume_fraction,
                               walls.walls.gap(), walls.packing.box.side());
    const PlugSlipLaw plug_slip =
        plug_law(walls, law, packing.skin, prm.base.shear_model.drag.rest_thickness);
    for (const std::string& row : plug_rows(packing.volume_fraction, packing.seed, plug_slip))
      plug.push_back(row);
    if (!options.quiet) {
      const std::vector<double> u = plug_slip.crossovers();
      std::cout << fmt::format("  plug slip law: sigma_w/E* = {:.4g} (V eta_s/(E* R))^1/2{}\n",
                               plug_slip.coefficient(),
                               u.empty() || u.back() == 0.0 ? std::string()
                                         : fmt::format(" above the films' crossovers U* = {:.2g} "
                                                       "(median; {:.2g} ... {:.2g})",
                                                       u[u.size() / 2], u.front(), u.back()));
    }
    std::filesystem::create_directories(runs);
    for (const double rate : spec.apparent_rates) {
      const std::string stem = fmt::format("phi{:.3f}_g{:.2e}_s{}", packing.volume_fraction, rate,
                                           packing.seed);
      const std::filesystem::path h5 = runs / (stem + ".h5"), row = runs / (stem + ".csv");
      if (std::filesystem::exists(h5) && std::filesystem::exists(row) && !options.force) {
        require(H5File::open(h5).root().read_string("parameters") == identity,
                fmt::format("{} is the finished result of another computation (other model, "
                            "packing or walls run settings): use another output directory, or "
                            "--force to replace it",
                            h5.string()));
        std::ifstream in(row);
        std::string line;
        std::getline(in, line);
        std::getline(in, line);
        rows.push_back(line);
        if (!options.quiet) std::cout << fmt::format("{}: done before, kept\n", stem);
        continue;
      }
      ShearModel model = prm.base.shear_model;
      model.gamma_tilde = rate;
      ContactSystem system(walls.packing.particles, walls.packing.box, law, packing.skin);
      system.set_walls(walls.walls);
      OverdampedShear flow(std::move(system), model);
      if (spec.solvent == SolventReference::local_mean)
        flow.set_solvent_flow(SolventFlow::local_mean(walls.walls.lower, walls.walls.upper));
      const auto integrator =
          make_integrator(scheme.resolved_for(rate, model.drag.stokes.reference));
      const WallRunResult run = run_wall_shear(flow, *integrator, spec.run);
      const WallRunSummary summary = summarise_wall_run(run);
      write_run(h5, run, summary, walls.walls, identity);
      const std::string line =
          summary_row(packing.volume_fraction, rate, packing.seed, walls.walls.gap(), summary);
      write_file(row, row.string(), [&](std::ostream& o) { o << summary_header() << '\n' << line << '\n'; });
      rows.push_back(line);
      if (!options.quiet)
        std::cout << fmt::format("{}: {} steps, {:.0f} s, sigma_w = {:.4g} ± {:.2g}, V_s = {:.4g} ± {:.2g}\n",
                                 stem, run.steps, run.seconds,
                                 find_estimate(summary.estimates, "wall_stress").mean,
                                 find_estimate(summary.estimates, "wall_stress").standard_error,
                                 find_estimate(summary.estimates, "slip_velocity").mean,
                                 find_estimate(summary.estimates, "slip_velocity").standard_error);
    }
  }
  const std::filesystem::path table = spec.directory / "slip.csv";
  write_file(table, table.string(), [&](std::ostream& o) {
    o << summary_header() << '\n';
    for (const std::string& r : rows) o << r << '\n';
  });
  const std::filesystem::path plug_table = spec.directory / "plug_slip.csv";
  write_file(plug_table, plug_table.string(), [&](std::ostream& o) {
    o << "phi,seed,slip_speed,wall_stress\n";
    for (const std::string& r : plug) o << r << '\n';
  });
  if (!options.quiet)
    std::cout << "table: " << table.string() << "\nplug slip law: " << plug_table.string() << '\n';
}

}  // namespace softglass::micro
