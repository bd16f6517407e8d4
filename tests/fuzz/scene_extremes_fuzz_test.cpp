// Values that are each acceptable but overflow together (issue 19, class 3):
// a radius of 1e60 m is within its entry's range, and so is an angular
// velocity of 1e60 rad/s, but the rim speed they make is not representable
// squared. Such input used to be a computation failure (exit 1, "rate scale =
// inf") after the reading had accepted it. The campaign sets two or three
// numeric entries of a scene (geometry, material, operating points) to powers
// of ten between 1e-99 and 1e99 at once, reads the file as `macro run` does
// (scene_reading.h), and solves the first and the last operating point of
// every file that is read: the input is either refused with an InputError or
// every number of the solution is finite. The scenes are the one-dimensional
// ones (infinite Couette cell, plane channel) at the fast preset, so that a
// solve costs milliseconds; the input checks are the same for every scene.
//
// It found that the checks bounded every dimensional scale but no
// dimensionless group: 78 of 300 Couette files were read and then failed in
// the solve. Since then the Bingham number and the flow index are bounded by
// the solver's measured envelope (input_scales.h, bench/solver_envelope.sh),
// and the solver and the exact reference were made to converge inside it; 1000
// files per scene pass (SOFTGLASS_FUZZ_ITERATIONS=1000).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "fuzz_check.h"
#include "scene_reading.h"
#include "tests/common/test_files.h"

namespace softglass::macro {
namespace {

using namespace softglass::testing::fuzz;
using softglass::testing::read_text;
using softglass::testing::write_text;

// The seed scene with the file it includes inlined (so that every entry is
// set once, in this file), in the 1D variant, at the fast preset.
std::string one_dimensional(const std::string& scene) {
  const auto cases = std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases";
  std::string text = read_text(cases / scene);
  std::smatch include;
  if (std::regex_search(text, include, std::regex(R"(include (\S+)\n)")))
    text = include.prefix().str() + read_text(cases / include[1].str()) + include.suffix().str();
  text = std::regex_replace(text, std::regex(R"(set end effects\s*=\s*true)"),
                            "set end effects = false");
  return std::regex_replace(text, std::regex(R"(set preset\s*=\s*\S+)"), "set preset = fast");
}

// Where the text sets a real number: the value's position and length.
// Counts (cells, points) are integers with their own small ranges.
struct NumberAt {
  std::string name;
  std::size_t at, length;
};
std::vector<NumberAt> real_entries(const std::string& text) {
  static const std::regex entry(R"(\n\s*set ([^=\n]+?)\s*=\s*([-+0-9.eE]+))");
  std::vector<NumberAt> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str();
    if (name.find("cells") != std::string::npos || name.find("points") != std::string::npos)
      continue;
    out.push_back({name, std::size_t((*it).position(2)), std::size_t((*it).length(2))});
  }
  return out;
}

TEST(SceneExtremesFuzz, CombinedExtremesAreRefusedOrSolvedToFiniteNumbers) {
  softglass::testing::TemporaryDirectory dir;
  const auto file = dir / "scene.prm";
  std::size_t read = 0, refused = 0;
  for (const char* scene : {"couette.prm", "channel.prm"}) {
    const std::string seed = one_dimensional(scene);
    const std::vector<NumberAt> numbers = real_entries(seed);
    ASSERT_GE(numbers.size(), 5u) << scene;
    const std::size_t budget = iterations(60);
    for (std::size_t iteration = 0; iteration < budget; ++iteration) {
      Mutator mutator(91, iteration);
      // Two or three entries, each set to 10^±(20 ... 99): within every
      // entry's own range of magnitudes (input_scales.h), extreme together.
      std::vector<std::pair<NumberAt, std::string>> changes;
      const std::size_t count = 2 + mutator.below(2);
      for (std::size_t k = 0; k < count; ++k) {
        const int exponent = int(20 + mutator.below(80)) * (mutator.below(2) == 0 ? 1 : -1);
        changes.emplace_back(mutator.pick(numbers), "1e" + std::to_string(exponent));
      }
      std::sort(changes.begin(), changes.end(),
                [](const auto& a, const auto& b) { return a.first.at > b.first.at; });
      std::string text = seed;
      std::string said;
      for (const auto& [where, value] : changes) {
        if (text.compare(where.at, where.length, seed, where.at, where.length) != 0) continue;
        text.replace(where.at, where.length, value);
        said += where.name + " = " + value + "; ";
      }
      write_text(file, text);
      const std::string input = describe(iteration, std::string(scene) + ": " + said, text);
      std::optional<testing::SceneAsRead> scene_read;
      if (!accepted([&] { scene_read.emplace(testing::read_scene_as_macro_run(file)); }, input)) {
        ++refused;
      } else {
        ++read;
        for (const double drive : {scene_read->points.front(), scene_read->points.back()}) {
          try {
            // Finite, but for the one column written NaN where the ideal
            // geometry's value is 0 (scene.h).
            const std::vector<double> values = scene_read->scene->solve(drive).values();
            const std::vector<Column> columns = scene_read->scene->columns();
            for (std::size_t c = 0; c < values.size(); ++c)
              if (!(std::isnan(values[c]) && columns[c].name == kUndefinedWhereIdealIsZero))
                expect_finite(values[c], columns[c].name, input);
          } catch (const std::exception& e) {
            ADD_FAILURE() << "read, then the solve at " << drive << " failed: " << e.what()
                          << "\n"
                          << input;
          }
        }
      }
      if (enough_failures()) return;
    }
  }
  // The campaign is only worth something if it reaches the solver too.
  EXPECT_GT(read, 10u);
  EXPECT_GT(refused, 10u);
}

}  // namespace
}  // namespace softglass::macro
