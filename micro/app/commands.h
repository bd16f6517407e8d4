// The `micro` subcommands: what each does, start to finish.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace softglass::micro {

struct CommandOptions {
  std::filesystem::path parameter_file;
  std::optional<std::filesystem::path> output;  // overrides the file's output entry
  bool force = false;                           // overwrite an existing output
  bool quiet = false;                           // no progress display
};

/// Make and relax a packing, measure it (Z, ε, Π, G0) and write it.
void pack_command(const CommandOptions& options);

/// Pack (or reuse a packing), shear at one γ̃ to a stationary state, summarise.
void run_command(const CommandOptions& options);

/// Structure analysis of a run file's stationary part, written into the file
/// (/structure, replaced only with `force`) and, with a `csv_prefix`, as CSV.
/// Entries of `settings` override those of the run.
struct AnalyzeOptions {
  std::filesystem::path run_file;
  std::string csv_prefix;
  bool force = false;
  std::optional<double> bin_width, slab;
};
void analyze_command(const AnalyzeOptions& options);

/// Average run files of one state point over their packings; print the table
/// and, if `csv` is not empty, write it as CSV with units.
void summary_command(const std::vector<std::filesystem::path>& runs,
                     const std::filesystem::path& csv, bool force);

}  // namespace softglass::micro
