#include "bridge/material/tabulated_material.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "bridge/material/interpolation.h"
#include "common/csv_table.h"
#include "common/errors.h"
#include "common/si_range.h"

namespace softglass::bridge {

namespace {

std::size_t column(const CsvTable& csv, const std::string& header) {
  const auto c = csv.find(header);
  require(c.has_value(), fmt::format("{}: no column '{}' (a table of `bridge fit`?)",
                                     csv.source(), header));
  return *c;
}

// The index of φ among the law's, within the 1e-9 of is_simulated.
std::optional<std::size_t> phi_index(const std::vector<double>& phi, double value) {
  for (std::size_t j = 0; j < phi.size(); ++j)
    if (std::abs(phi[j] - value) < 1e-9) return j;
  return std::nullopt;
}

}  // namespace

SimulatedCurves read_simulated_curves(const std::filesystem::path& law_file, const Law& law) {
  const std::filesystem::path points_file = beside(law_file, "_points.csv"),
                              phi_file = beside(law_file, "_phi.csv");
  for (const auto& f : {points_file, phi_file})
    require(std::filesystem::exists(f),
            fmt::format("--tabulated needs the simulated points `bridge fit` writes beside the law "
                        "file: {} is missing",
                        f.string()));
  SimulatedCurves out;
  out.phi = law.phi;
  const std::size_t n_phi = law.phi.size();

  const CsvTable phis = CsvTable::read(phi_file);
  const std::size_t pc = column(phis, "phi [1]"),
                    yc = column(phis, "sigma_yield_quasi_static [E*]"),
                    yse = column(phis, "sigma_yield_quasi_static_se [E*]");
  out.quasi_static_yield.assign(n_phi, Estimate{-1.0, 0.0});
  for (std::size_t r = 0; r < phis.rows(); ++r)
    if (const auto j = phi_index(law.phi, phis.number(r, pc)))
      out.quasi_static_yield[*j] = {phis.number(r, yc), phis.number(r, yse)};
  for (std::size_t j = 0; j < n_phi; ++j)
    require(out.quasi_static_yield[j].value >= 0.0,
            fmt::format("{}: no quasi-static yield stress at phi = {}", phi_file.string(),
                        law.phi[j]));

  const CsvTable points = CsvTable::read(points_file);
  const std::size_t ppc = column(points, "phi [1]"), gc = column(points, "gamma_tilde [1]");
  // [quantity][γ̃][φ]: what each row holds, then the rates every φ has.
  std::map<double, std::vector<std::optional<Estimate>>> by_rate[3];
  const Quantity quantities[] = {Quantity::sigma, Quantity::N1, Quantity::N2};
  for (const Quantity q : quantities) {
    const std::string name = column_name(q);
    const auto vc = points.find(name + " [E*]"), sc = points.find(name + "_se [E*]");
    if (!vc || !sc) {
      require(q != Quantity::sigma, fmt::format("{}: no column 'sigma [E*]' with its "
                                                "'sigma_se [E*]'",
                                                points_file.string()));
      continue;
    }
    auto& rows = by_rate[index(q)];
    for (std::size_t r = 0; r < points.rows(); ++r) {
      const auto j = phi_index(law.phi, points.number(r, ppc));
      if (!j) continue;
      auto& slot = rows[points.number(r, gc)];
      slot.resize(n_phi);
      slot[*j] = Estimate{points.number(r, *vc), points.number(r, *sc)};
    }
  }
  for (const auto& [gamma, slots] : by_rate[index(Quantity::sigma)])
    if (gamma > 0.0 && std::all_of(slots.begin(), slots.end(), [](const auto& e) { return e; }))
      out.gamma_tilde.push_back(gamma);
  require(out.gamma_tilde.size() >= 2,
          fmt::format("{}: fewer than two rates simulated at every volume fraction of the law",
                      points_file.string()));
  for (const Quantity q : quantities) {
    const auto& rows = by_rate[index(q)];
    if (rows.empty()) continue;
    auto& table = out.values[index(q)].emplace();
    for (const double gamma : out.gamma_tilde) {
      std::vector<Estimate> at_phi;
      for (const auto& e : rows.at(gamma)) at_phi.push_back(*e);
      table.push_back(std::move(at_phi));
    }
  }
  return out;
}

TabulatedMaterial make_tabulated_material(const Law& law, const SimulatedCurves& curves,
                                          const MaterialRequest& request) {
  check_request(law, request);
  const double e_star = request.modulus, time = request.viscosity / request.modulus;
  const auto scaled = [e_star](MaterialValue v) {
    return MaterialValue{e_star * v.value, e_star * v.statistical, e_star * v.interpolation};
  };
  TabulatedMaterial m;
  m.request = request;
  m.placement = describe_placement(law, request.phi);
  m.yield = scaled(interpolate_value(law.phi, curves.quasi_static_yield, request.phi));
  for (const Quantity q : {Quantity::N1, Quantity::N2})
    if (curves.values[index(q)] && law.hb[index(q)])
      m.rest[index(q)] = scaled(interpolate_value(law.phi, law.hb[index(q)]->yield, request.phi));
  for (std::size_t i = 0; i < curves.gamma_tilde.size(); ++i) {
    TabulatedRow row{.rate = curves.gamma_tilde[i] / time, .value = {}};
    for (const Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2})
      if (const auto& table = curves.values[index(q)])
        row.value[index(q)] = scaled(interpolate_value(law.phi, (*table)[i], request.phi));
    m.rows.push_back(std::move(row));
  }
  // What macro's tabulated law requires (tabulated_law.h), said here with the
  // simulated rates, where the cause is. The steady stress at a finite rate
  // is at least the quasi-static yield stress (its γ̇ → 0 limit), so a lowest
  // rate whose stress comes out at or below it lies on the yield plateau
  // within the scatter of both: those rows are left out, and the law reaches
  // τ_y through its continuation below the window instead.
  for (const TabulatedRow& row : m.rows) {
    require(within_si_range(row.rate) && within_si_range(m.yield.value),
            fmt::format("at E* = {:.3g} Pa, eta_s = {:.3g} Pa s the table's rates or stresses "
                        "({:.3g} 1/s, tau_y = {:.3g} Pa) fall outside 0 or magnitudes 1e-100 ... "
                        "1e100 (SI) that macro solves with",
                        e_star, request.viscosity, row.rate, m.yield.value));
    for (const auto& value : row.value)
      require(!value || within_si_range(value->value),
              fmt::format("at E* = {:.3g} Pa the stress {:.3g} Pa at {:.3g} 1/s falls outside 0 "
                          "or magnitudes 1e-100 ... 1e100 (SI) that macro solves with",
                          e_star, value ? value->value : 0.0, row.rate));
  }
  const auto sigma = [&m](std::size_t i) { return m.rows[i].value[index(Quantity::sigma)]->value; };
  while (!m.rows.empty() && sigma(0) <= m.yield.value) {
    m.plateau_rows.push_back(m.rows.front());
    m.rows.erase(m.rows.begin());
  }
  require(m.rows.size() >= 2,
          fmt::format("at phi = {} the simulated stresses exceed the quasi-static yield stress "
                      "{:.4g} Pa at fewer than two rates: no flow curve to tabulate (use the "
                      "Herschel-Bulkley material)",
                      request.phi, m.yield.value));
  for (std::size_t i = 1; i < m.rows.size(); ++i)
    require(sigma(i) > sigma(i - 1),
            fmt::format("the simulated stress does not increase from {:.3g} to {:.3g} 1/s "
                        "({:.5g} -> {:.5g} Pa) at phi = {}: within the packings' scatter, the "
                        "sweep needs more packings or longer runs there",
                        m.rows[i - 1].rate, m.rows[i].rate, sigma(i - 1), sigma(i), request.phi));
  return m;
}

std::string tabulated_material_text(const TabulatedMaterial& m,
                                    const std::vector<std::string>& provenance) {
  std::string out;
  for (const std::string& line : provenance) out += "# " + line + "\n";
  out += fmt::format(
      "# phi = {}, E* = {:.6g} Pa, eta_s = {:.6g} Pa s: {}\n"
      "# simulated shear rates {:.3g} ... {:.3g} 1/s; outside them macro extrapolates as power "
      "laws (docs/material-format.md)\n"
      "# errors (one standard deviation): statistical (the packings), interpolation (in phi)\n",
      m.request.phi, m.request.modulus, m.request.viscosity, m.placement, m.rows.front().rate,
      m.rows.back().rate);
  out += error_comment("tau_y", m.yield, "Pa");
  for (const TabulatedRow& row : m.plateau_rows)
    out += fmt::format(
        "# left out: {:.3g} 1/s, tau = {:.6g} Pa +- {:.2g} Pa, not above tau_y (the yield plateau "
        "within the scatter); below the first row the law continues as a power law to tau_y\n",
        row.rate, row.value[index(Quantity::sigma)]->value,
        row.value[index(Quantity::sigma)]->error());
  for (const TabulatedRow& row : m.rows)
    for (const Quantity q : {Quantity::sigma, Quantity::N1, Quantity::N2})
      if (const auto& v = row.value[index(q)])
        out += error_comment(fmt::format("{}({:.3g})", q == Quantity::sigma ? "tau" : column_name(q),
                                         row.rate),
                             *v, "Pa");
  const auto list = [&m](auto of_row) {
    std::vector<std::string> items;
    for (const TabulatedRow& row : m.rows) items.push_back(fmt::format("{:.6g}", of_row(row)));
    return fmt::format("{}", fmt::join(items, ", "));
  };
  const auto value_of = [](Quantity q) {
    return [q](const TabulatedRow& row) { return row.value[index(q)]->value; };
  };
  out += "subsection material\n";
  out += "  # The simulated flow curve point by point (monotone cubic in log-log between rates).\n";
  out += "  set model        = tabulated\n";
  if (!m.source.empty()) out += fmt::format("  set source       = {}\n", m.source);
  out += fmt::format("  set yield stress = {:.6g}   # tau_y [Pa], the quasi-static limit\n",
                     m.yield.value);
  out += fmt::format("  set rates        = {}   # [1/s]\n", list([](const TabulatedRow& row) { return row.rate; }));
  out += fmt::format("  set stresses     = {}   # [Pa]\n", list(value_of(Quantity::sigma)));
  for (const Quantity q : {Quantity::N1, Quantity::N2}) {
    if (!m.rows.front().value[index(q)]) continue;
    const std::string name = column_name(q);
    out += fmt::format("  set {} values    = {}   # [Pa]\n", name, list(value_of(q)));
    out += fmt::format("  set {} yield     = {:.6g}   # [Pa], at rest\n", name,
                       m.rest[index(q)] ? m.rest[index(q)]->value : 0.0);
  }
  out += "end\n";
  return out;
}

}  // namespace softglass::bridge
