// Errors shared by every softglass tool, and the exit codes they map to.
//
// Every entry point (micro, bridge, macro) reports a problem as one line naming
// what is wrong, the offending value and what is allowed, and exits with one of
// the codes below. Tests and scripts rely on these codes.
#pragma once

#include <cstdio>
#include <functional>
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

/// Runs a tool's command and turns what it throws into one line on stderr,
/// "tool: error: message", and the exit code of its kind; otherwise returns
/// the command's own code.
inline int run_reporting_errors(const char* tool, const std::function<int()>& command) {
  const auto fail = [tool](int code, const char* message) {
    std::fprintf(stderr, "%s: error: %s\n", tool, message);
    return code;
  };
  try {
    return command();
  } catch (const InputError& e) {
    return fail(kExitBadInput, e.what());
  } catch (const OutputExistsError& e) {
    return fail(kExitOutputExists, e.what());
  } catch (const std::exception& e) {
    return fail(kExitFailure, e.what());
  }
}

}  // namespace softglass
