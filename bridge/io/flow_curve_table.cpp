#include "bridge/io/flow_curve_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "bridge/io/table_columns.h"
#include "common/errors.h"
#include "common/flow_curve_columns.h"

namespace softglass::bridge {

const char* column_name(Quantity q) {
  static constexpr std::array<const char*, kQuantities> names = {
      flow_curve::shear_stress, flow_curve::first_normal_difference,
      flow_curve::second_normal_difference, flow_curve::contact_force};
  return names[index(q)];
}

const char* reduced_units(Quantity q) {
  return q == Quantity::force ? "E*R^2" : "E*";
}

namespace {

// A quantity's value by its sign rule (flow_curve_table.h).
double quantity(const TableColumns& columns, Quantity q, std::size_t r, std::size_t c) {
  if (may_be_negative(q)) return columns.number(r, c);
  return may_be_zero(q) ? columns.nonnegative(r, c) : columns.positive(r, c);
}

// A flow-curve table's header: units checked against the format.
TableColumns flow_curve_columns(const CsvTable& csv) {
  return TableColumns(csv, flow_curve::unit_of, "docs/flow-curve-format.md",
                      "flow-curve tables are in reduced units (stresses in E*, forces in E* R^2), "
                      "all columns alike");
}

// The value columns (and, if `with_errors`, their standard-error columns) present.
PerQuantity<std::pair<std::size_t, std::size_t>> value_columns(const TableColumns& columns,
                                                               const CsvTable& csv,
                                                               bool with_errors) {
  PerQuantity<std::pair<std::size_t, std::size_t>> result;
  for (Quantity q : kAllQuantities) {
    const std::string name = column_name(q);
    const auto value = q == Quantity::sigma ? columns.require(name) : columns.find(name);
    const auto error = columns.find(flow_curve::error_of(name));
    if (!value) {
      if (error)
        throw InputError(fmt::format("{}: '{}_se' without '{}'", csv.source(), name, name));
      continue;
    }
    result[index(q)] = {*value, with_errors ? columns.require(flow_curve::error_of(name)) : 0};
  }
  return result;
}

}  // namespace

FlowCurveTable read_flow_curve_table(const CsvTable& csv) {
  const TableColumns columns = flow_curve_columns(csv);
  const std::size_t phi = columns.require(flow_curve::phi),
                    rate = columns.require(flow_curve::gamma_tilde),
                    packings = columns.require(flow_curve::packings),
                    g0 = columns.require(flow_curve::shear_modulus),
                    g0_se = columns.require(flow_curve::error_of(flow_curve::shear_modulus));
  const auto converged = columns.find(flow_curve::converged);
  const auto quantities = value_columns(columns, csv, true);

  FlowCurveTable table;
  table.source = csv.source();
  table.comments = csv.comments();
  for (Quantity q : kAllQuantities) table.present[index(q)] = quantities[index(q)].has_value();
  std::map<std::pair<double, double>, std::size_t> seen;  // (φ, γ̃) → line
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    StatePoint p;
    p.line = csv.line(r);
    p.phi = columns.fraction(r, phi);
    p.gamma_tilde = columns.rate(r, rate);
    p.packings = static_cast<std::size_t>(columns.count(r, packings, 1));
    if (converged) {
      const double n = columns.count(r, *converged, 0);
      if (n > static_cast<double>(p.packings)) {
        throw InputError(fmt::format("{}: {} (must be at most packings = {})",
                                     csv.where(r, *converged), n, p.packings));
      }
      p.converged = static_cast<std::size_t>(n);
    }
    p.modulus = {columns.positive(r, g0), columns.value(
                                              r, g0_se, [](double v) { return v >= 0; }, ">= 0")};
    for (Quantity q : kAllQuantities) {
      const auto& c = quantities[index(q)];
      if (!c) continue;
      p.values[index(q)] =
          Estimate{quantity(columns, q, r, c->first), columns.positive(r, c->second)};
    }
    const auto [it, fresh] = seen.emplace(std::pair(p.phi, p.gamma_tilde), p.line);
    if (!fresh) {
      throw InputError(
          fmt::format("{}, line {}: state point phi = {}, gamma~ = {} already on line {}",
                      csv.source(), p.line, p.phi, p.gamma_tilde, it->second));
    }
    table.points.push_back(p);
  }
  if (table.points.empty()) throw InputError(csv.source() + ": the table has no rows");
  return table;
}

void merge_structure(FlowCurveTable& table, const CsvTable& csv) {
  const std::size_t force = index(Quantity::force);
  if (table.present[force]) {
    throw InputError(
        fmt::format("{}: the flow-curve table {} has f_m columns already; give the "
                    "structure once",
                    csv.source(), table.source));
  }
  const TableColumns columns = flow_curve_columns(csv);
  const std::size_t phi = columns.require(flow_curve::phi),
                    rate = columns.require(flow_curve::gamma_tilde),
                    value = columns.require(column_name(Quantity::force)),
                    error = columns.require(flow_curve::error_of(column_name(Quantity::force)));
  // Rows are matched to state points as make_sweep groups them: φ and γ̃ equal
  // to within a relative 1e-9 (both files print them from the same numbers).
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
  std::vector<std::size_t> from_line(table.points.size(), 0);
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const double p = columns.fraction(r, phi), g = columns.rate(r, rate);
    const auto it =
        std::find_if(table.points.begin(), table.points.end(),
                     [&](const StatePoint& s) { return same(p, s.phi) && same(g, s.gamma_tilde); });
    if (it == table.points.end()) {
      throw InputError(fmt::format("{}, line {}: phi = {}, gamma~ = {} is not a state point of {}",
                                   csv.source(), csv.line(r), p, g, table.source));
    }
    const auto i = static_cast<std::size_t>(it - table.points.begin());
    if (from_line[i] != 0) {
      throw InputError(fmt::format("{}, line {}: phi = {}, gamma~ = {} already on line {}",
                                   csv.source(), csv.line(r), p, g, from_line[i]));
    }
    from_line[i] = csv.line(r);
    it->values[force] = Estimate{columns.nonnegative(r, value), columns.positive(r, error)};
  }
  for (std::size_t i = 0; i < table.points.size(); ++i) {
    if (from_line[i] == 0) {
      throw InputError(
          fmt::format("{}: no row for phi = {}, gamma~ = {} ({}, line {}); the force "
                      "law needs f_m at every state point",
                      csv.source(), table.points[i].phi, table.points[i].gamma_tilde, table.source,
                      table.points[i].line));
    }
  }
  table.present[force] = true;
}

std::vector<PackingRun> read_packing_runs(const CsvTable& csv) {
  const TableColumns columns = flow_curve_columns(csv);
  const std::size_t phi = columns.require(flow_curve::phi),
                    rate = columns.require(flow_curve::gamma_tilde),
                    seed = columns.require(flow_curve::seed),
                    g0 = columns.require(flow_curve::shear_modulus);
  const auto quantities = value_columns(columns, csv, false);
  std::vector<PackingRun> runs;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    PackingRun run;
    run.line = csv.line(r);
    run.phi = columns.fraction(r, phi);
    run.gamma_tilde = columns.rate(r, rate);
    run.seed = static_cast<std::uint64_t>(columns.count(r, seed, 0));
    run.modulus = columns.positive(r, g0);
    for (Quantity q : kAllQuantities) {
      const auto& c = quantities[index(q)];
      if (!c) continue;
      run.values[index(q)] = quantity(columns, q, r, c->first);
    }
    runs.push_back(run);
  }
  if (runs.empty()) throw InputError(csv.source() + ": the per-packing table has no rows");
  return runs;
}

void keep_rates(const RateWindow& window, FlowCurveTable& table, std::vector<PackingRun>& runs) {
  require(std::isfinite(window.lowest) && window.lowest >= 0.0 && window.highest > window.lowest,
          fmt::format("the rate window gamma~ = {:g} ... {:g} is empty or reversed", window.lowest,
                      window.highest));
  // The edges as written in a table (1e-05 against 1.0000000000e-05) are inside.
  constexpr double kEdge = 1e-9;
  const auto outside = [&](double gamma_tilde) {
    return gamma_tilde > 0.0 && (gamma_tilde < window.lowest * (1.0 - kEdge) ||
                                 gamma_tilde > window.highest * (1.0 + kEdge));
  };
  std::erase_if(table.points, [&](const StatePoint& p) { return outside(p.gamma_tilde); });
  std::erase_if(runs, [&](const PackingRun& r) { return outside(r.gamma_tilde); });
}

}  // namespace softglass::bridge
