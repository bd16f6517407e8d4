#include "micro/results/flow_curve_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <utility>
#include <stdexcept>

#include "common/h5_file.h"

namespace softglass::micro {

namespace {

// The stress columns of docs/flow-curve-format.md, each followed by its `_se`.
const std::vector<std::string>& stress_columns() {
  static const std::vector<std::string> names = {
      "sigma", "sigma_elastic", "sigma_viscous", "N1", "N1_elastic", "N1_viscous",
      "N2",    "N2_elastic",    "N2_viscous",    "pressure"};
  return names;
}

void add_column(NumberTable& t, const std::string& name, const std::string& units) {
  t.names.push_back(name);
  t.units.push_back(units);
}

void add_stress_columns(NumberTable& t) {
  for (const auto& name : stress_columns()) {
    add_column(t, name, "E*");
    add_column(t, name + "_se", "E*");
  }
}

// r_m and f_m with their errors, when every row has them (docs/structure.md).
void add_structure_columns(NumberTable& t) {
  for (const auto& [name, units] : {std::pair{"r_m", "R"}, std::pair{"f_m", "E*R^2"}}) {
    add_column(t, name, units);
    add_column(t, std::string(name) + "_se", units);
  }
}

}  // namespace

NumberTable flow_curve_table(const std::vector<PackingAverage>& points) {
  NumberTable t;
  const bool structure =
      !points.empty() && std::all_of(points.begin(), points.end(), [](const auto& p) { return p.f_m.has_value(); });
  add_column(t, "phi", "1");
  add_column(t, "gamma_tilde", "1");
  add_column(t, "packings", "1");
  add_stress_columns(t);
  add_column(t, "Z", "1");
  add_column(t, "G0", "E*");
  add_column(t, "G0_se", "E*");
  add_column(t, "converged", "1");
  if (structure) add_structure_columns(t);
  for (const auto& p : points) {
    std::vector<double> row = {p.volume_fraction, p.gamma_tilde, static_cast<double>(p.runs)};
    for (const auto& name : stress_columns()) {
      row.push_back(p[name].mean);
      row.push_back(p[name].standard_error());
    }
    row.insert(row.end(), {p.coordination, p.shear_modulus, p.shear_modulus_error,
                           static_cast<double>(p.converged_runs)});
    if (structure)
      row.insert(row.end(), {p.r_m->mean, p.r_m->standard_error(), p.f_m->mean, p.f_m->standard_error()});
    t.rows.push_back(std::move(row));
  }
  return t;
}

NumberTable per_packing_table(const std::vector<StoredRunSummary>& runs,
                              const std::vector<unsigned>& seeds) {
  NumberTable t;
  const bool structure =
      !runs.empty() && std::all_of(runs.begin(), runs.end(), [](const auto& r) { return r.f_m.has_value(); });
  add_column(t, "phi", "1");
  add_column(t, "gamma_tilde", "1");
  add_column(t, "seed", "1");
  add_stress_columns(t);
  add_column(t, "Z", "1");
  add_column(t, "G0", "E*");
  if (structure) add_structure_columns(t);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const StoredRunSummary& r = runs[k];
    std::vector<double> row = {r.volume_fraction, r.gamma_tilde, static_cast<double>(seeds.at(k))};
    for (const auto& name : stress_columns()) {
      const MeanEstimate& e = find_estimate(r.observables, name);
      row.push_back(e.mean);
      row.push_back(e.standard_error);
    }
    row.insert(row.end(), {r.coordination, r.shear_modulus});
    if (structure) row.insert(row.end(), {r.r_m->value, r.r_m->error, r.f_m->value, r.f_m->error});
    t.rows.push_back(std::move(row));
  }
  return t;
}

void write_table_csv(const std::filesystem::path& path, const NumberTable& table,
                     const std::vector<std::string>& provenance) {
  std::ofstream f(path);
  for (const auto& line : provenance) f << "# " << line << '\n';
  for (std::size_t c = 0; c < table.names.size(); ++c)
    f << (c ? "," : "") << table.names[c] << " [" << table.units[c] << ']';
  f << '\n';
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) f << (c ? "," : "") << fmt::format("{:.10g}", row[c]);
    f << '\n';
  }
  f.close();
  if (!f) throw std::runtime_error("writing " + path.string() + " failed");
}

void write_tables_h5(const std::filesystem::path& path, const std::vector<NamedTable>& tables,
                     const std::vector<std::string>& provenance) {
  H5File file = H5File::create(path);
  std::string lines;
  for (const auto& line : provenance) lines += line + '\n';
  for (const auto& [name, table] : tables) {
    H5Group group = file.root().create_group(name);
    group.set_attribute("provenance", lines);
    group.set_attribute("rows", table->rows.size());
    for (std::size_t c = 0; c < table->names.size(); ++c) {
      std::vector<double> column;
      for (const auto& row : table->rows) column.push_back(row[c]);
      group.write(table->names[c], column, {}, {.units = table->units[c]});
    }
  }
  file.close();
}

}  // namespace softglass::micro
