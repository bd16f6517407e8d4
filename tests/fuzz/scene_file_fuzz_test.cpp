// Fuzzing the macro scene file (macro/app/scene_file.h) with mutations of the
// scenes of cases/, read as `macro run` reads them (scene_reading.h).
#include <gtest/gtest.h>

#include "fuzz_check.h"
#include "scene_reading.h"
#include "tests/common/test_files.h"

namespace softglass::macro {
namespace {

using namespace softglass::testing::fuzz;
using softglass::testing::read_text;
using softglass::testing::write_text;

TEST(SceneFileFuzz, RefusesOrReadsEveryMutation) {
  softglass::testing::TemporaryDirectory dir;
  const auto cases = std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases";
  // The material fragments the scenes include, beside the scene as in cases/.
  for (const auto& entry : std::filesystem::directory_iterator(cases)) {
    const std::string name = entry.path().filename().string();
    if (name.find("material") != std::string::npos)
      std::filesystem::copy_file(entry.path(), dir / name);
  }
  std::vector<std::string> seeds;
  for (const char* scene : {"couette.prm", "channel.prm", "cone_plate.prm", "duct.prm"})
    seeds.push_back(read_text(cases / scene));
  const auto file = dir / "scene.prm";
  fuzz_text(seeds, 81, 400, [&](const std::string& text, const std::string& input) {
    write_text(file, text);
    return read_and_check(
        [&] { return testing::read_scene_as_macro_run(file).points; },
        [&](const std::vector<double>& points) {
          EXPECT_FALSE(points.empty()) << input;
          expect_all_finite(points, "an operating point", input);
          for (const double p : points) EXPECT_GT(p, 0.0) << input;
        },
        input);
  });
}

}  // namespace
}  // namespace softglass::macro
