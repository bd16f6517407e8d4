#include "micro/results/flow_curve_table.h"

#include <algorithm>
#include <utility>

#include "common/flow_curve_columns.h"
#include "common/h5_file.h"

namespace softglass::micro {

namespace {

namespace columns = softglass::flow_curve;

void add_column(UnitTable& t, const std::string& name) {
  t.columns.push_back({name, columns::unit_of(name)});
}

// A quantity and its standard error.
void add_with_error(UnitTable& t, const std::string& name) {
  add_column(t, name);
  add_column(t, columns::error_of(name));
}

void add_stress_columns(UnitTable& t) {
  for (const char* name : columns::stresses) add_with_error(t, name);
}

// r_m and f_m with their errors, when every row has them (docs/structure.md).
void add_structure_columns(UnitTable& t) {
  add_with_error(t, columns::contact_distance);
  add_with_error(t, columns::contact_force);
}

}  // namespace

UnitTable flow_curve_table(const std::vector<PackingAverage>& points) {
  UnitTable t;
  const bool structure =
      !points.empty() && std::all_of(points.begin(), points.end(), [](const auto& p) { return p.f_m.has_value(); });
  for (const char* name : {columns::phi, columns::gamma_tilde, columns::packings}) add_column(t, name);
  add_stress_columns(t);
  add_column(t, columns::coordination);
  add_with_error(t, columns::shear_modulus);
  add_column(t, columns::converged);
  if (structure) add_structure_columns(t);
  for (const auto& p : points) {
    std::vector<double> row = {p.volume_fraction, p.gamma_tilde, static_cast<double>(p.runs)};
    for (const char* name : columns::stresses) {
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

UnitTable per_packing_table(const std::vector<StoredRunSummary>& runs,
                            const std::vector<unsigned>& seeds) {
  UnitTable t;
  const bool structure =
      !runs.empty() && std::all_of(runs.begin(), runs.end(), [](const auto& r) { return r.f_m.has_value(); });
  for (const char* name : {columns::phi, columns::gamma_tilde, columns::seed}) add_column(t, name);
  add_stress_columns(t);
  add_column(t, columns::coordination);
  add_column(t, columns::shear_modulus);
  if (structure) add_structure_columns(t);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const StoredRunSummary& r = runs[k];
    std::vector<double> row = {r.volume_fraction, r.gamma_tilde, static_cast<double>(seeds.at(k))};
    for (const char* name : columns::stresses) {
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

void write_table_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
                     const UnitTable& table, const std::vector<std::string>& provenance) {
  write_csv(path, shown_path, provenance, table, 10);
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
    write_columns(group, *table);
  }
  file.close();
}

}  // namespace softglass::micro
