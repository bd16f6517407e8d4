// `macro compare SCENE.prm DATA.csv`: the scene's predicted torques (and normal
// forces) at the angular velocities of a measured curve, point by point, with
// relative errors, a summary and an overlay plot.
#pragma once

#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "common/measured_curves.h"

namespace softglass::macro::app {

struct CompareOptions {
  std::filesystem::path scene_file;
  std::filesystem::path data_file;
  /// Empty: <data stem>_vs_<scene stem> in the current directory.
  std::filesystem::path output;
  /// The curve's label when the file holds several (a sample column, pairs).
  std::string sample;
  /// The file's export format and the units of rate and stress columns
  /// without units in their header.
  MeasuredReading reading;
  /// The instrument's constants when they differ from the geometry's standard ones.
  std::optional<double> strain_constant, stress_constant;
  /// Only points whose shear rate lies in this window [1/s].
  double min_rate = 0.0;
  double max_rate = std::numeric_limits<double>::infinity();
  std::string preset;
  /// A material fragment replacing the scene's material when not empty.
  std::filesystem::path material;
  /// MPI ranks that share one operating point's mesh; 0 = chosen (operating_points.h).
  unsigned ranks_per_point = 0;
  /// Compare at most this many of the points (thinned evenly); 0: all of them,
  /// refused beyond kMostComparedPoints.
  std::size_t max_points = 0;
  bool force = false;
  bool quiet = false;
};

/// More points than this in the rate window are refused unless --max-points
/// thins them (common/measured_curves.h).
inline constexpr std::size_t kMostComparedPoints = kMostMeasuredPoints;

/// Returns the exit code; throws InputError, OutputExistsError, NumericalError.
int compare(const CompareOptions& options);

}  // namespace softglass::macro::app
