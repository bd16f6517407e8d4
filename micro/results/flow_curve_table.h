// The flow-curve table of a sweep (docs/flow-curve-format.md): one row per
// state point (φ, γ̃) averaged over its packings, and the companion table with
// one row per run, for estimates over packings (bootstrap). Written as CSV with
// units in every column name and as HDF5 (one dataset per column).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/unit_table.h"
#include "micro/io/run_file.h"
#include "micro/results/packing_average.h"

namespace softglass::micro {

/// One row per state point, in the order given.
UnitTable flow_curve_table(const std::vector<PackingAverage>& points);

/// One row per run; `seeds[k]` is the packing seed of `runs[k]`.
UnitTable per_packing_table(const std::vector<StoredRunSummary>& runs,
                            const std::vector<unsigned>& seeds);

/// CSV with `#` provenance lines before the header, every number with 10
/// significant digits (more than any average carries); `path` is written whole
/// (the caller makes it atomic), errors name `shown_path`.
void write_table_csv(const std::filesystem::path& path, const std::filesystem::path& shown_path,
                     const UnitTable& table, const std::vector<std::string>& provenance);

/// The tables as groups `name` of an HDF5 file: a dataset per column with its
/// units; `provenance` as the group's attribute.
struct NamedTable {
  std::string name;
  const UnitTable* table;
};
void write_tables_h5(const std::filesystem::path& path, const std::vector<NamedTable>& tables,
                     const std::vector<std::string>& provenance);

}  // namespace softglass::micro
