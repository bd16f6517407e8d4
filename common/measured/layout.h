// A layout of measured files: how a rheometer export arranges its curves in
// columns. Each layout is one file that defines its registry entry and one
// line in registered_layouts.h; read_rheometer_curves takes the first layout,
// in that list's order, that recognises the file's header.
#pragma once

#include <string>
#include <vector>

#include "common/csv_table.h"
#include "common/measured_curves.h"
#include "common/registry.h"

namespace softglass::measured {

/// A layout: its name and summary, the test of a header that recognises it,
/// and its reader, which returns the file's curves in SI units (InputError
/// naming the file, the line and the column for anything it cannot read);
/// `fallback`: the command line's units, for headers that give none.
struct LayoutEntry {
  std::string name;
  std::string summary;
  bool (*recognises)(const std::vector<std::string>& header) = nullptr;
  std::vector<RheometerCurve> (*read)(const CsvTable& csv,
                                      const MeasuredReading& fallback) = nullptr;
};

/// Every layout, in the order they are tried.
const Registry<LayoutEntry>& layouts();

}  // namespace softglass::measured
