// Scene files that are valid, entry by entry, but say something else than the
// user meant (issue 19, class 2): a file without `set scene` beside a
// subsection channel ran the default cone and plate, taking the channel's
// pressure gradients for angular velocities. The campaign builds every such
// file from the scenes of cases/ and the subsection of every registered scene,
// and reads each as `macro run` does (scene_reading.h):
//   - another scene's subsection added (one per registered scene);
//   - `set scene` pointed at another scene, the file's own subsection left;
//   - `set scene` removed (the default scene then applies);
//   - an entry set a second time with another value;
// each must be refused with an InputError naming the offending entry. Its
// control, which a reader refusing everything would fail: the scene switched
// whole (`set scene` and the subsection both replaced) must be read. One
// misreading of each kind per seed also goes to `macro run` itself: exit 2,
// the entry named, no result folder left.
#include <gtest/gtest.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "fuzz_check.h"
#include "scene_reading.h"
#include "tests/common/command_line.h"
#include "tests/common/test_files.h"

namespace softglass::macro {
namespace {

using softglass::testing::read_text;
using softglass::testing::write_text;

// The declared scenes: the default of `set scene`, and the subsection of
// every registered scene with each entry at its default, as deal.II prints a
// declared parameter set.
struct DeclaredScenes {
  std::string default_scene;
  std::map<std::string, std::string> blocks;
};

DeclaredScenes declared_scenes() {
  dealii::ParameterHandler prm;
  declare_scenes(prm);
  std::ostringstream printed;
  prm.print_parameters(printed, dealii::ParameterHandler::ShortPRM);
  DeclaredScenes declared{.default_scene = prm.get("scene"), .blocks = {}};
  std::istringstream in(printed.str());
  std::string line, current;
  static const std::regex opening(R"(^subsection (.+)$)");
  for (std::smatch m; std::getline(in, line);) {
    if (std::regex_match(line, m, opening)) current = m[1].str();
    if (!current.empty()) declared.blocks[current] += line + "\n";
    if (line == "end") current.clear();
  }
  return declared;
}

// `text` with its line `set scene = <from>` made `set scene = <to>`, or
// removed when `to` is empty.
std::string with_scene(std::string text, const std::string& from, const std::string& to) {
  const std::string line = "set scene = " + from + "\n";
  text.replace(text.find(line), line.size(), to.empty() ? "" : "set scene = " + to + "\n");
  return text;
}

// The file's subsection `name` ... end, and the file without it.
std::string block_of(const std::string& text, const std::string& name, std::string* rest) {
  const std::regex block("\\nsubsection " + name + "\\n[\\s\\S]*?\\nend\\n");
  std::smatch m;
  if (!std::regex_search(text, m, block)) return {};
  *rest = m.prefix().str() + "\n" + m.suffix().str();
  return m.str();
}

struct Variant {
  std::string description;
  std::string text;
  std::string named;  // what the refusal must name; empty: must be read
};

std::vector<Variant> variants(const std::string& seed, const std::string& scene,
                              const DeclaredScenes& declared) {
  std::vector<Variant> out;
  std::string without_own;
  const std::string own = block_of(seed, scene, &without_own);
  EXPECT_FALSE(own.empty()) << "the seed of " << scene << " has no subsection " << scene;
  for (const auto& [other, block] : declared.blocks) {
    if (other == scene) continue;
    out.push_back({"subsection " + other + " added", seed + block, "'" + other + "/"});
    out.push_back({"scene set to " + other + ", subsection " + scene + " kept",
                   with_scene(seed, scene, other), "'" + scene + "/"});
    out.push_back({"switched whole to " + other, with_scene(without_own + block, scene, other),
                   ""});
  }
  if (scene != declared.default_scene)
    out.push_back({"set scene removed", with_scene(seed, scene, ""), "does not set scene"});
  // The first entry of the scene's subsection, set again on the next line.
  static const std::regex first_entry(R"(\n\s*set ([^=\n]+?)\s*=[^\n]*\n)");
  std::smatch m;
  if (std::regex_search(own, m, first_entry)) {
    std::string repeated = seed;
    repeated.insert(seed.find(own) + m.position(0) + m.length(0),
                    "  set " + m[1].str() + " = 1e-3\n");
    out.push_back({"'" + m[1].str() + "' set twice", repeated, "set a second time"});
  }
  return out;
}

// "subsection channel added" -> "subsection added": what kind of misreading.
std::string kind_of(const std::string& description) {
  return std::regex_replace(description, std::regex(R"((to|subsection) [a-z-]+)"), "$1");
}

// `macro run` itself on scene.prm in `dir`: exit 2 with a message naming
// `named`, and no result folder left behind.
void expect_refused_by_the_tool(const std::filesystem::path& dir, const std::string& named,
                                const std::string& input) {
  const softglass::testing::Outcome o = softglass::testing::run_tool(
      SOFTGLASS_MACRO_EXECUTABLE, "run scene.prm -o out -q", dir, dir / "capture");
  EXPECT_EQ(o.code, 2) << o.err << "\n" << input;
  EXPECT_NE(o.err.find(named), std::string::npos) << o.err << "\n" << input;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "a refused run left a folder\n" << input;
}

TEST(SceneSemanticsFuzz, EveryMisreadingIsRefusedNamingItsEntry) {
  softglass::testing::TemporaryDirectory dir;
  const auto cases = std::filesystem::path(SOFTGLASS_SOURCE_DIR) / "cases";
  for (const auto& entry : std::filesystem::directory_iterator(cases))
    if (entry.path().filename().string().find("material") != std::string::npos)
      std::filesystem::copy_file(entry.path(), dir / entry.path().filename());
  const DeclaredScenes declared = declared_scenes();
  const std::size_t registered = declared.blocks.size();
  ASSERT_GE(registered, 4u);
  const std::map<std::string, std::string> seeds = {{"couette", "couette.prm"},
                                                    {"channel", "channel.prm"},
                                                    {"cone-plate", "cone_plate.prm"},
                                                    {"duct", "duct.prm"}};
  std::size_t tried = 0, refused = 0, read = 0;
  const auto file = dir / "scene.prm";
  for (const auto& [scene, name] : seeds) {
    std::set<std::string> kinds_run;  // one misreading of each kind per seed, as a process
    for (const Variant& v : variants(read_text(cases / name), scene, declared)) {
      ++tried;
      write_text(file, v.text);
      const std::string input = name + ": " + v.description + "\n---- input\n" + v.text;
      if (!v.named.empty() && kinds_run.insert(kind_of(v.description)).second)
        expect_refused_by_the_tool(dir.path(), v.named, input);
      try {
        testing::read_scene_as_macro_run(file);
        ++read;
        softglass::testing::fuzz::count_input(true);
        EXPECT_TRUE(v.named.empty()) << "read, not refused\n" << input;
      } catch (const InputError& e) {
        ++refused;
        softglass::testing::fuzz::count_input(false);
        if (v.named.empty()) {
          ADD_FAILURE() << "a consistent file refused: " << e.what() << "\n" << input;
        } else {
          EXPECT_NE(std::string(e.what()).find(v.named), std::string::npos)
              << "the refusal does not name " << v.named << ": " << e.what() << "\n"
              << input;
        }
      } catch (const std::exception& e) {
        ADD_FAILURE() << "threw " << typeid(e).name() << " instead of InputError: " << e.what()
                      << "\n"
                      << input;
      }
      if (softglass::testing::fuzz::enough_failures()) return;
    }
  }
  // Every registered scene grafted into and switched to from every seed; the
  // scene removed from the seeds that do not choose the default; one entry
  // repeated in each.
  EXPECT_EQ(tried, seeds.size() * 3 * (registered - 1) + (seeds.size() - 1) + seeds.size());
  EXPECT_EQ(read, seeds.size() * (registered - 1));
  EXPECT_EQ(refused, tried - read);
}

}  // namespace
}  // namespace softglass::macro
