// Command-line errors in the same form as every other error of the tools
// (errors.h): one line "tool: error: ..." on stderr and exit code 2. CLI11's
// own report is two lines without the tool's name, and its range validators
// print DBL_MAX in full; the tools use `positive` below instead.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/errors.h"
#include "common/measured_file.h"

namespace softglass {

/// --help and --version print as CLI11 does (exit 0); anything else → one
/// line naming the tool and the problem, exit code 2.
inline int report_command_line_error(const char* tool, CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return app.exit(e);
  std::string message = e.what();
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::fprintf(stderr, "%s: error: %s (%s --help lists the options)\n", tool, message.c_str(), tool);
  return kExitBadInput;
}

/// A number > 0 (and finite), with a message that says so.
inline const CLI::Validator positive(
    [](const std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !(value > 0.0) || !std::isfinite(value))
        return "value " + text + " is not allowed; allowed: a finite number > 0";
      return {};
    },
    "POSITIVE");

/// --format FORMAT: the export format of the measured file `which` names.
inline CLI::Option* add_measured_format_option(CLI::App& command, std::string& format,
                                               const std::string& which) {
  return command
      .add_option("--format", format,
                  "export format of " + which +
                      " (default auto: detected; docs/measured-files.md describes each)")
      ->check(CLI::IsMember(measured_file_formats()));
}

}  // namespace softglass
