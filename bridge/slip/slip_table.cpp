#include "bridge/slip/slip_table.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "common/errors.h"

namespace softglass::bridge {

namespace {

// The units a column may carry; "" for a ratio of the run's own scales.
const std::map<std::string, std::string>& known_units() {
  static const std::map<std::string, std::string> units{
      {"phi", "1"},           {"gamma_app", "1"},
      {"wall_stress", "E*"},  {"wall_stress_se", "E*"},
      {"slip_velocity", "gamma_dot R"}, {"slip_velocity_se", "gamma_dot R"},
      {"bulk_rate", "gamma_dot"},       {"converged", "1"}};
  return units;
}

}  // namespace

SlipTable read_slip_table(const CsvTable& csv) {
  std::map<std::string, std::size_t> index;
  for (std::size_t c = 0; c < csv.columns(); ++c) {
    const ColumnName column = split_units(csv.header()[c]);
    const auto known = known_units().find(column.name);
    if (known != known_units().end() && !column.units.empty() && column.units != known->second)
      throw InputError(fmt::format(
          "{}: column '{}' is in '{}', expected '{}' (the reduced units of `micro slip`, "
          "docs/bridge.md 'Wall slip')",
          csv.source(), csv.header()[c], column.units, known->second));
    if (!index.emplace(column.name, c).second)
      throw InputError(fmt::format("{}: column '{}' appears twice", csv.source(), column.name));
  }
  const auto column = [&](const std::string& name) {
    const auto it = index.find(name);
    if (it == index.end())
      throw InputError(fmt::format(
          "{}: column '{}' is missing (a slip table of `micro slip` has phi, gamma_app, "
          "wall_stress, wall_stress_se, slip_velocity, slip_velocity_se)",
          csv.source(), name));
    return it->second;
  };
  const std::size_t phi = column("phi"), rate = column("gamma_app"), stress = column("wall_stress"),
                    stress_se = column("wall_stress_se"), slip = column("slip_velocity"),
                    slip_se = column("slip_velocity_se");
  const auto optional_column = [&](const std::string& name) -> std::optional<std::size_t> {
    const auto it = index.find(name);
    return it == index.end() ? std::nullopt : std::optional(it->second);
  };
  const auto bulk = optional_column("bulk_rate"), converged = optional_column("converged"),
             seed = optional_column("seed"), gap = optional_column("gap");

  const auto checked = [&](std::size_t r, std::size_t c, bool ok, const std::string& rule) {
    const double v = csv.number(r, c);
    if (!ok) throw InputError(fmt::format("{}: {} (must be {})", csv.where(r, c), v, rule));
    return v;
  };
  SlipTable table{csv.source(), csv.comments(), {}};
  std::vector<std::string> seeds;  // per row, "" without a seed column
  require(csv.rows() > 0, fmt::format("{}: the slip table has no rows", csv.source()));
  // Every cell a finite number, used or not: a table with gaps is not trusted.
  for (std::size_t r = 0; r < csv.rows(); ++r)
    for (std::size_t c = 0; c < csv.columns(); ++c) csv.number(r, c);
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    SlipRow row;
    row.line = csv.line(r);
    row.phi = csv.number(r, phi);
    checked(r, phi, row.phi > 0 && row.phi < 1, "in (0, 1)");
    row.gamma_app = csv.number(r, rate);
    checked(r, rate, row.gamma_app > 0, "> 0");
    row.wall_stress = {csv.number(r, stress), csv.number(r, stress_se)};
    checked(r, stress, row.wall_stress.value > 0, "> 0: the slip law is fitted in log-log");
    checked(r, stress_se, row.wall_stress.error >= 0, ">= 0");
    row.slip_velocity = {csv.number(r, slip), csv.number(r, slip_se)};
    checked(r, slip, row.slip_velocity.value > 0, "> 0: the slip law is fitted in log-log");
    checked(r, slip_se, row.slip_velocity.error >= 0, ">= 0");
    if (gap) {
      // Each wall slips by at most half the walls' relative velocity γ̇_app H:
      // Ṽ ≤ H / (2R), the gap being in R.
      const double most = 0.5 * csv.number(r, *gap);
      checked(r, slip,
              row.slip_velocity.value <= 1.01 * most + 3 * row.slip_velocity.error,
              fmt::format("at most gap/2 = {:.6g}: a wall cannot slip faster than the walls move "
                          "apart",
                          most));
    }
    if (bulk) row.bulk_rate = csv.number(r, *bulk);
    if (converged) {
      const double v = csv.number(r, *converged);
      checked(r, *converged, v == 0 || v == 1, "0 or 1");
      row.converged = v == 1;
    }
    // Runs of different packings (seeds) at one state point are independent
    // samples; the same run listed twice is not.
    for (std::size_t k = 0; k < table.rows.size(); ++k) {
      const SlipRow& before = table.rows[k];
      if (std::abs(before.phi - row.phi) <= 1e-9 * row.phi &&
          std::abs(before.gamma_app - row.gamma_app) <= 1e-9 * row.gamma_app &&
          (!seed || seeds[k] == csv.text(r, *seed))) {
        throw InputError(fmt::format(
            "{}, line {}: phi = {}, gamma_app = {}{} is already on line {}; one run listed twice "
            "would weigh twice in the fit and narrow its errors",
            csv.source(), row.line, row.phi, row.gamma_app,
            seed ? fmt::format(", seed {}", csv.text(r, *seed)) : "", before.line));
      }
    }
    table.rows.push_back(row);
    seeds.push_back(seed ? csv.text(r, *seed) : "");
  }
  return table;
}

}  // namespace softglass::bridge
