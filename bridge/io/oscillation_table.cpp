#include "bridge/io/oscillation_table.h"

#include <fmt/format.h>

#include <map>
#include <tuple>

#include "bridge/io/table_columns.h"
#include "common/errors.h"
#include "common/oscillation_columns.h"

namespace softglass::bridge {

OscillationTable read_oscillation_table(const CsvTable& csv) {
  namespace columns = oscillation_table;
  const TableColumns c(csv, columns::unit_of, "docs/oscillation.md",
                       "oscillation tables are in reduced units (moduli in E*), all columns alike");
  const std::size_t phi = c.require(columns::phi), frequency = c.require(columns::frequency),
                    amplitude = c.require(columns::amplitude),
                    packings = c.require(columns::packings), storage = c.require(columns::storage),
                    storage_se = c.require(columns::error_of(columns::storage)),
                    loss = c.require(columns::loss),
                    loss_se = c.require(columns::error_of(columns::loss)),
                    g0 = c.require(columns::shear_modulus),
                    g0_se = c.require(columns::error_of(columns::shear_modulus));
  const std::optional<std::size_t> converged = c.find(columns::converged);
  OscillationTable table;
  table.source = csv.source();
  table.comments = csv.comments();
  std::map<std::tuple<double, double, double>, std::size_t> seen;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    OscillationPoint p;
    p.line = csv.line(r);
    p.phi = c.fraction(r, phi);
    p.frequency = c.positive(r, frequency);
    p.amplitude = c.positive(r, amplitude);
    p.packings = static_cast<std::size_t>(c.count(r, packings, 1));
    p.storage = {c.number(r, storage), c.nonnegative(r, storage_se)};
    p.loss = {c.number(r, loss), c.nonnegative(r, loss_se)};
    p.modulus = {c.positive(r, g0), c.nonnegative(r, g0_se)};
    const auto [it, fresh] = seen.emplace(std::tuple(p.phi, p.frequency, p.amplitude), p.line);
    if (!fresh)
      throw InputError(
          fmt::format("{}, line {}: phi = {}, omega~ = {}, gamma0 = {} already on line {}",
                      csv.source(), p.line, p.phi, p.frequency, p.amplitude, it->second));
    const std::string where = fmt::format("line {} (phi = {}, gamma0 = {})", p.line, p.phi,
                                          p.amplitude);
    if (converged) {
      const double met = c.number(r, *converged);
      if (met < static_cast<double>(p.packings))
        table.warnings.push_back(fmt::format(
            "{}: {} of {} runs did not meet their stopping rule (no periodic state reached)",
            where, static_cast<double>(p.packings) - met, p.packings));
    }
    for (const auto& [name, value] : {std::pair("G'", p.storage), std::pair("G''", p.loss)}) {
      if (value.value < -2 * value.error)
        table.warnings.push_back(fmt::format(
            "{}: {} = {:.3g} +- {:.2g} E* is negative beyond its error: not a steady "
            "oscillation's modulus",
            where, name, value.value, value.error));
    }
    table.points.push_back(p);
  }
  if (table.points.empty()) throw InputError(csv.source() + ": the table has no rows");
  return table;
}

}  // namespace softglass::bridge
