// `bridge slip-law`: the wall slip law of a `micro slip` table
// (bridge/slip/slip_law.h), per volume fraction in reduced units, and with
// E*, η_s and R the `subsection slip` of a macro scene at one φ.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "bridge/app/command_support.h"
#include "bridge/app/commands.h"
#include "bridge/app/law_file.h"
#include "bridge/material/interpolation.h"
#include "bridge/slip/slip_law.h"
#include "common/errors.h"

namespace softglass::bridge {

namespace {

// σ̃_y(φ) of a law file, for --below-yield.
std::function<double(double)> yield_limit(const Law& law, const std::string& source) {
  return [&law, source](double phi) {
    require(phi >= law.phi.front() - 1e-9 && phi <= law.phi.back() + 1e-9,
            fmt::format("--below-yield {}: the slip table's phi = {} lies outside the law's "
                        "volume fractions {} ... {}",
                        source, phi, law.phi.front(), law.phi.back()));
    return interpolate(law.phi, law.hb[index(Quantity::sigma)]->yield, phi).value;
  };
}

std::string goodness_line(const SlipLawFit& f) {
  const GoodnessOfFit& g = f.goodness;
  if (g.dof <= 0) return "2 rows: the law passes through both; its errors are theirs alone";
  std::string line = fmt::format(
      "chi2/dof = {:.3g} with the rows' own standard errors ({} dof, p-value {:.2g})",
      g.reduced_chi2(), g.dof, g.p_value);
  if (f.scatter > 0)
    line += fmt::format(
        "; the law misses its rows beyond their errors: a scatter of {:.2g} % about it is added to "
        "every row's error, and the errors of A and p rest on it",
        100.0 * f.scatter);
  return line;
}

std::vector<std::string> fit_lines(const SlipTableFit& t) {
  const SlipLawFit& f = t.law;
  std::vector<std::string> lines;
  lines.push_back(fmt::format(
      "phi = {}: {} of {} rows fitted (wall stress {:.4g} ... {:.4g} E*{})", f.phi, f.points,
      t.rows.size(), f.stress_min, f.stress_max,
      std::isfinite(t.stress_limit) ? fmt::format("; limit {:.4g} E*", t.stress_limit) : ""));
  lines.push_back(fmt::format(
      "  V~ gamma~ = A sigma~_w^p: A = {:.6g} (ln A = {:.6g} +- {:.3g}), p = {:.6g} +- {:.3g}, "
      "corr(ln A, p) = {:.4f}",
      std::exp(f.log_coefficient.value), f.log_coefficient.value, f.log_coefficient.error,
      f.exponent.value, f.exponent.error, f.correlation));
  lines.push_back("  goodness: " + goodness_line(f));
  lines.push_back(fmt::format(
      "  best determined at sigma~_w = {:.4g}: V~ gamma~ = {:.4g} +- {:.2g} %", f.pivot_stress(),
      std::exp(f.log_coefficient.value) * std::pow(f.pivot_stress(), f.exponent.value),
      100.0 * f.pivot_error()));
  return lines;
}

std::vector<std::string> row_lines(const SlipTableFit& t) {
  const SlipLawFit& f = t.law;
  std::vector<std::string> lines{fmt::format("  {:>10} {:>12} {:>12} {:>9} {:>10}", "gamma_app",
                                             "sigma_w [E*]", "V~ gamma~", "bulk/app",
                                             "data/law-1")};
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const SlipRow& r = *t.rows[k];
    const double v = r.slip_velocity.value * r.gamma_app;
    const double law =
        std::exp(f.log_coefficient.value) * std::pow(r.wall_stress.value, f.exponent.value);
    lines.push_back(fmt::format(
        "  {:>10.3g} {:>12.5g} {:>12.5g} {:>9} {:>+9.2f}%  {}{}", r.gamma_app, r.wall_stress.value,
        v, r.bulk_rate ? fmt::format("{:.3f}", *r.bulk_rate) : std::string("-"),
        100.0 * (v / law - 1.0), t.fitted[k] ? "fitted" : "left out",
        r.converged ? "" : " (run not converged)"));
  }
  return lines;
}

}  // namespace

void slip_law_command(const SlipLawOptions& o, const std::string& command_line) {
  std::optional<AtomicOutput> out;
  if (!o.output.empty()) out.emplace(o.output, o.force);
  const SlipTable table = read_slip_table(CsvTable::read(o.table));
  std::optional<Law> law;
  std::function<double(double)> limit = [&](double) {
    return o.max_stress.value_or(std::numeric_limits<double>::infinity());
  };
  std::string limit_text = o.max_stress ? fmt::format("wall stress <= {:.4g} E* (--max-stress)",
                                                      *o.max_stress)
                                        : std::string("all rows");
  if (!o.below_yield.empty()) {
    law = read_law_file(o.below_yield);
    const auto yield = yield_limit(*law, o.below_yield.string());
    limit = [&, yield](double phi) {
      return std::min(yield(phi), o.max_stress.value_or(std::numeric_limits<double>::infinity()));
    };
    limit_text = fmt::format("wall stress <= the yield stress sigma_y(phi) of {}{}",
                             o.below_yield.string(), o.max_stress ? " and --max-stress" : "");
  }
  const std::vector<SlipTableFit> fits = fit_slip_table(table, limit);

  std::vector<std::string> lines = provenance(
      "softglass bridge slip-law: a wall slip law from a `micro slip` table", command_line);
  std::size_t unconverged = 0;
  for (const SlipRow& r : table.rows) unconverged += r.converged ? 0 : 1;
  lines.push_back(fmt::format("table:    {} ({} rows, {} volume fraction{}); fitted: {}",
                              o.table.string(), table.rows.size(), fits.size(),
                              fits.size() == 1 ? "" : "s", limit_text));
  for (const std::string& c : table.comments) lines.push_back("table |   " + c);
  if (unconverged > 0)
    lines.push_back(fmt::format("WARNING:  {} of {} rows come from runs that did not meet their "
                                "stopping rule (converged = 0)",
                                unconverged, table.rows.size()));
  lines.push_back(
      "reduced law per phi (V~ in units of gamma_dot_app R, sigma~_w in E*, gamma~ = gamma_app):");
  for (const SlipTableFit& t : fits)
    for (const auto& group : {fit_lines(t), row_lines(t)})
      lines.insert(lines.end(), group.begin(), group.end());
  const auto print_report = [&lines] {
    for (std::size_t k = 3; k < lines.size(); ++k) fmt::print("{}\n", lines[k]);
  };

  const bool si = o.modulus || o.viscosity || o.radius;
  if (!si) {
    require(!out, "-o writes the macro slip law: give --modulus, --viscosity and --radius");
    print_report();
    return;
  }
  require(o.modulus && o.viscosity && o.radius,
          "the SI slip law needs all of --modulus (E* [Pa]), --viscosity (eta_s [Pa s]) and "
          "--radius (R [m])");
  require(o.phi || fits.size() == 1,
          fmt::format("the table holds {} volume fractions: choose one with --phi", fits.size()));
  const double phi = o.phi.value_or(fits.front().law.phi);
  const SlipLawAt at = slip_law_at(fits, phi, o.extrapolate);
  const double a = std::exp(at.log_coefficient.value), p = at.exponent.value;
  const double beta = slip_coefficient_si(a, p, *o.modulus, *o.viscosity, *o.radius);
  const double e = *o.modulus, scale = e * *o.radius / *o.viscosity;  // V_s per unit V~ gamma~
  const std::vector<std::string> si_lines{
      fmt::format("phi = {}: {}", phi, at.placement),
      fmt::format("E* = {:.6g} Pa, eta_s = {:.6g} Pa s, R = {:.6g} m: beta = A R E*^(1-p) / eta_s "
                  "= {:.6g} m/s/Pa^p +- {:.2g} % (from the errors of ln A and p and their "
                  "correlation), p = {:.6g} +- {:.3g}",
                  e, *o.viscosity, *o.radius, beta,
                  100.0 * slip_coefficient_relative_error(at, e), p, at.exponent.error),
      fmt::format("beta is proportional to R: the droplet or particle radius is the one number the "
                  "slip law needs beyond the bulk law's E* and eta_s (docs/bridge.md 'Wall slip')"),
      fmt::format("fitted wall stresses {:.4g} ... {:.4g} Pa, slip velocities {:.4g} ... {:.4g} "
                  "m/s; beyond them the law is extrapolated",
                  at.stress_min * e, at.stress_max * e,
                  scale * a * std::pow(at.stress_min, p), scale * a * std::pow(at.stress_max, p)),
      "smooth walls only: on roughened or serrated tools leave `slip walls` empty"};
  lines.insert(lines.end(), si_lines.begin(), si_lines.end());
  const std::string text = slip_law_text(lines, beta, p);
  if (!out) {  // the fragment alone, its report in comments: `> slip.prm` works
    fmt::print("{}", text);
    return;
  }
  print_report();
  write(*out, text);
  out->commit();
  fmt::print("written  {}\n", out->final_path().string());
}

}  // namespace softglass::bridge
