// `macro run FILE.prm`: solve the scene at every operating point of the sweep
// and write results.csv, results.h5, summary.txt and ParaView files into the
// output directory.
#pragma once

#include <filesystem>
#include <string>

namespace softglass::macro::app {

struct RunOptions {
  std::filesystem::path scene_file;
  /// Empty: <scene file stem>_results in the current directory.
  std::filesystem::path output;
  bool force = false;
  bool quiet = false;
  /// Overrides the file's solver preset when not empty.
  std::string preset;
  /// A material fragment replacing the scene's material when not empty.
  std::filesystem::path material;
  /// MPI ranks that share one operating point's mesh; 0 = chosen (operating_points.h).
  unsigned ranks_per_point = 0;
};

/// Returns the exit code; throws InputError, OutputExistsError, NumericalError.
int run(const RunOptions& options);

/// Prints the documented template of a scene file (every entry, its default,
/// unit and allowed values).
void print_template();

}  // namespace softglass::macro::app
