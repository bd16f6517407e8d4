// `micro oscillate`: amplitude and frequency sweeps of oscillatory shear.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "micro/app/workers.h"

namespace softglass::micro {

struct OscillateOptions {
  std::filesystem::path parameter_file;
  std::string command_line;              // recorded in the tables
  bool quiet = false;                    // no progress bar (log lines stay)
  bool list = false;                     // print the cases and their state, run nothing
  bool gather_only = false;              // only rebuild the tables from finished runs
  std::optional<std::size_t> only_case;  // batch-array mode: this case alone
};

/// Runs what is missing of the oscillation sweep, then writes its tables.
/// Throws InputError for a bad file or a folder locked by another sweep, and
/// NumericalError when runs failed (the table then holds the others).
void oscillate_command(const OscillateOptions& options, const Workers& workers);

}  // namespace softglass::micro
