// docs/parameters.md is made by scripts/parameter_reference.sh from the built
// micro, bridge and macro (their templates and --help). The committed page must
// be what the script makes of this build's tools, so that a new or changed
// entry or option cannot leave it behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "tests/common/command_line.h"
#include "tests/common/test_files.h"

namespace softglass::testing {
namespace {

const std::filesystem::path kSource = SOFTGLASS_SOURCE_DIR;

// The first line in which `a` and `b` differ (1-based), with both versions.
std::string first_difference(const std::string& committed, const std::string& generated) {
  std::istringstream a(committed), b(generated);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a && !more_b) return "they differ only in line ends";
    if (!more_a || !more_b || line_a != line_b) {
      return "first difference at line " + std::to_string(line) + ":\n  committed: " +
             (more_a ? line_a : "(end of file)") + "\n  generated: " +
             (more_b ? line_b : "(end of file)");
    }
  }
}

TEST(ParameterReference, CommittedPageIsCurrent) {
  TemporaryDirectory directory;
  ASSERT_EQ(setenv("SOFTGLASS_MICRO", SOFTGLASS_MICRO_EXECUTABLE, 1), 0);
  ASSERT_EQ(setenv("SOFTGLASS_BRIDGE", SOFTGLASS_BRIDGE_EXECUTABLE, 1), 0);
  ASSERT_EQ(setenv("SOFTGLASS_MACRO", SOFTGLASS_MACRO_EXECUTABLE, 1), 0);
  const std::filesystem::path script = kSource / "scripts" / "parameter_reference.sh";
  const Outcome o = run_tool("bash", "'" + script.string() + "' '" SOFTGLASS_BUILD_DIR "'",
                             directory.path(), directory / "capture");
  ASSERT_EQ(o.code, 0) << o.err;

  const std::string committed = read_text(kSource / "docs" / "parameters.md");
  EXPECT_TRUE(committed == o.out)
      << "docs/parameters.md is not what the tools print now ("
      << first_difference(committed, o.out) << ").\nRegenerate it, from " << kSource.string()
      << ", with\n  scripts/parameter_reference.sh " SOFTGLASS_BUILD_DIR " > docs/parameters.md";
}

}  // namespace
}  // namespace softglass::testing
