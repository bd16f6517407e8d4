// Errors shared by every softglass tool, and the exit codes they map to.
//
// Every entry point (micro, bridge, macro) reports a problem as one line naming
// what is wrong, the offending value and what is allowed, and exits with one of
// the codes below. Tests and scripts rely on these codes.
#pragma once

#include <stdexcept>
#include <string>

namespace softglass {

enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,       // the computation failed (numerical breakdown, I/O error)
  kExitBadInput = 2,      // malformed or non-physical input, bad command line
  kExitOutputExists = 3,  // refusing to overwrite an existing result
};

/// Malformed, missing, out-of-range or non-physical input.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical method did not reach its tolerance.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The output path already holds a file and overwriting was not asked for.
class OutputExistsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws InputError unless `condition` holds; the message should name the
/// parameter, its value and the allowed range.
inline void require(bool condition, const std::string& message) {
  if (!condition) throw InputError(message);
}

}  // namespace softglass
