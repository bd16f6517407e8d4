// micro's folders are layers that include only downward
// (scripts/check_micro_layers.py): the source tree has no upward include, and
// the check does catch one.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "micro_test_support.h"
#include "tests/common/command_line.h"

namespace softglass::micro {
namespace {

namespace fs = std::filesystem;

const fs::path kScript = fs::path(SOFTGLASS_SOURCE_DIR) / "scripts" / "check_micro_layers.py";

::softglass::testing::Outcome check(const fs::path& root, const fs::path& scratch) {
  return ::softglass::testing::run_tool(
      "/usr/bin/python3", fmt::format("'{}' '{}'", kScript.string(), root.string()), root, scratch);
}

TEST(MicroLayers, SourceTreeHasNoUpwardInclude) {
  ::softglass::testing::TemporaryDirectory scratch;
  const ::softglass::testing::Outcome o = check(SOFTGLASS_SOURCE_DIR, scratch.path());
  EXPECT_EQ(o.code, 0) << o.out << o.err;
  EXPECT_NE(o.out.find("no upward include"), std::string::npos) << o.out;
}

TEST(MicroLayers, AnUpwardIncludeFailsTheCheck) {
  ::softglass::testing::TemporaryDirectory tree;
  for (const char* layer : {"geometry", "model"}) fs::create_directories(tree / "micro" / layer);
  ::softglass::testing::write_text(tree / "micro" / "geometry" / "box.h",
                                   "#include \"micro/geometry/x.h\"\n");
  ::softglass::testing::write_text(tree / "micro" / "model" / "system.h",
                                   "// a model header\n#include \"micro/protocol/shear_run.h\"\n");
  const ::softglass::testing::Outcome o = check(tree.path(), tree / "capture");
  EXPECT_EQ(o.code, 1) << o.out << o.err;
  EXPECT_NE(o.out.find("micro/model/system.h:2: model -> protocol"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("1 upward include"), std::string::npos) << o.out;
}

}  // namespace
}  // namespace softglass::micro
