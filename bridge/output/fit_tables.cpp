#include <fmt/format.h>

#include <cmath>

#include "bridge/law/law.h"
#include "common/csv_table.h"
#include "common/csv_writer.h"
#include "bridge/output/tables.h"

namespace softglass::bridge {

namespace {

std::string column(Quantity q, const std::string& what, const std::string& units) {
  return fmt::format("{}_{} [{}]", column_name(q), what, units);
}

bool has(const SweepAnalysis& a, Quantity q) {
  return a.sweep.present[index(q)];
}

// The quasi-static σ_y goes beside the fitted one when the table has γ̃ = 0 rows.
bool quasi_static_beside(const SweepAnalysis& a, Quantity q) {
  return q == Quantity::sigma && a.sweep.quasi_static_points() > 0;
}

}  // namespace

std::string phi_table(const SweepAnalysis& a, const std::vector<std::string>& comments) {
  std::vector<std::string> header = {"phi [1]",
                                     "G0 [E*]",
                                     "G0_se [E*]",
                                     "gamma_y [1]",
                                     "gamma_y_se [1]",
                                     "gamma_y_universal [1]",
                                     "gamma_y_universal_se [1]"};
  for (Quantity q : kAllQuantities) {
    if (!has(a, q)) continue;
    const std::string u = reduced_units(q);
    for (const std::string& name : {std::string("yield"), std::string("consistency")}) {
      header.push_back(column(q, name, u));
      header.push_back(column(q, name + "_se", u));
      if (name == "yield" && quasi_static_beside(a, q)) {
        header.push_back(column(q, "yield_quasi_static", u));
        header.push_back(column(q, "yield_quasi_static_se", u));
      }
    }
    header.push_back(column(q, "exponent", "1"));
    header.push_back(column(q, "exponent_se", "1"));
    header.push_back(column(q, "chi2_dof", "1"));
    header.push_back(column(q, "p", "1"));
    if (q == Quantity::force) continue;
    header.push_back(column(q, "own_k", "1"));
    header.push_back(column(q, "own_k_se", "1"));
    header.push_back(column(q, "universal_yield", u));
    header.push_back(column(q, "universal_yield_se", u));
  }
  if (has(a, Quantity::force)) {
    for (const char* name : {"f_y [E*R^2]", "f_y_se [E*R^2]", "k_f [E*R^2]", "k_f_se [E*R^2]"})
      header.push_back(name);
  }
  CsvWriter w("the phi table", header, comments);
  // n/a: the quasi-static σ_y of a φ without its γ̃ = 0 row; the goodness of a
  // fit without degrees of freedom; every value of a normal-stress or force
  // law whose fit failed (warned; only the stress law must fit, and a failed
  // one is refused before this table).
  for (const std::string& h : header) {
    const std::string name = split_units(h).name;
    const bool optional_law = !name.starts_with(std::string(column_name(Quantity::sigma)) + "_") &&
                              name != "phi" && !name.starts_with("G0") &&
                              !name.starts_with("gamma_y") && !name.starts_with("universal_gamma_y");
    if (optional_law || name.ends_with("_yield_quasi_static") || name.ends_with("_chi2_dof") ||
        name.ends_with("_p"))
      w.may_be_na(name);
  }
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const GroupFit &v = a.estimate.fit.groups[j], &e = a.uncertainty.error.groups[j];
    w << v.phi << v.modulus << e.modulus << v.yield_strain << e.yield_strain
      << v.universal_yield_strain << e.universal_yield_strain;
    for (Quantity q : kAllQuantities) {
      if (!has(a, q)) continue;
      const HbParameters &pv = *v.hb[index(q)], &pe = *e.hb[index(q)];
      const GoodnessOfFit& g = a.estimate.diagnostics.hb[j][index(q)]->goodness;
      w << pv.yield << pe.yield;
      if (quasi_static_beside(a, q)) {  // NaN for a φ without its γ̃ = 0 row
        const auto& row = a.sweep.groups[j].quasi_static;
        w << (row ? row->values[index(q)]->value : NAN)
          << (row ? row->values[index(q)]->error : NAN);
      }
      w << pv.consistency << pe.consistency << pv.exponent << pe.exponent << g.reduced_chi2()
        << g.p_value;
      if (q == Quantity::force) continue;
      w << *v.own_k[index(q)] << *e.own_k[index(q)] << *v.universal_yield[index(q)]
        << *e.universal_yield[index(q)];
    }
    if (has(a, Quantity::force))
      w << *v.force_yield << *e.force_yield << *v.force_slope << *e.force_slope;
    w.end_row();
  }
  return w.text();
}

std::string points_table(const SweepAnalysis& a, const std::vector<std::string>& comments) {
  std::vector<std::string> header = {"phi [1]", "gamma_tilde [1]", "collapse_rate [1]"};
  for (Quantity q : kAllQuantities) {
    if (!has(a, q)) continue;
    const std::string u = reduced_units(q), name = column_name(q);
    header.push_back(fmt::format("{} [{}]", name, u));
    header.push_back(fmt::format("{}_se [{}]", name, u));
    header.push_back(fmt::format("{}_weight_se [{}]", name, u));
    header.push_back(fmt::format("{}_herschel_bulkley [{}]", name, u));
    if (q != Quantity::force) header.push_back(fmt::format("{}_ratio [1]", name));
  }
  CsvWriter w("the points table", header, comments);
  // n/a: the curve of a normal-stress or force law whose fit failed (warned).
  for (Quantity q : kAllQuantities)
    if (q != Quantity::sigma && has(a, q))
      w.may_be_na(fmt::format("{}_herschel_bulkley", column_name(q)));
  for (std::size_t j = 0; j < a.sweep.groups.size(); ++j) {
    const PhiGroup& g = a.sweep.groups[j];
    const GroupFit& f = a.estimate.fit.groups[j];
    const std::vector<double>& rates = g.curves[index(Quantity::sigma)]->x;
    for (std::size_t i = 0; i < rates.size(); ++i) {
      w << g.phi << rates[i] << collapse_rate(rates[i], f.universal_yield_strain);
      for (Quantity q : kAllQuantities) {
        if (!has(a, q)) continue;
        const Curve& c = *g.curves[index(q)];
        w << c.y[i] << (*g.table_errors[index(q)])[i] << c.se[i] << (*f.hb[index(q)])(rates[i]);
        if (q != Quantity::force)
          w << universal_sign(q) * c.y[i] / *f.universal_yield[index(Quantity::sigma)];
      }
      w.end_row();
    }
  }
  return w.text();
}

std::string constants_table(const SweepAnalysis& a, const std::vector<std::string>& comments) {
  CsvWriter w("the constants table", {"constant", "value [1]", "error [1]", "paper [1]", "paper_error [1]",
                         "collapse_chi2_dof [1]", "collapse_p [1]"}, comments);
  w.may_be_na("collapse_chi2_dof");  // the mean exponent is no collapse
  w.may_be_na("collapse_p");
  const std::pair<Quantity, Estimate> paper[] = {{Quantity::sigma, PaperValues::k},
                                                 {Quantity::N1, PaperValues::k_N1},
                                                 {Quantity::N2, PaperValues::k_N2}};
  for (const auto& [q, reference] : paper) {
    if (!a.estimate.fit.k[index(q)]) continue;
    const auto& collapse = a.collapse[index(q)];
    w << (q == Quantity::sigma ? std::string("k") : "k_" + std::string(column_name(q)))
      << *a.estimate.fit.k[index(q)] << *a.uncertainty.error.k[index(q)] << reference.value
      << reference.error << (collapse ? collapse->reduced_chi2() : NAN)
      << (collapse ? collapse->p_value : NAN);
    w.end_row();
  }
  w << std::string("mean_exponent") << a.estimate.fit.mean_exponent
    << a.uncertainty.error.mean_exponent << PaperValues::exponent.value
    << PaperValues::exponent.error << NAN << NAN;
  w.end_row();
  return w.text();
}

}  // namespace softglass::bridge
