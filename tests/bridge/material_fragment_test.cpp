// The material fragment `bridge material` writes, read as macro will read it:
// with deal.II's ParameterHandler, against docs/material-format.md's entries
// and rules. (Its own executable: deal.II is slow to load, see CMakeLists.txt.)
#include <deal.II/base/parameter_handler.h>
#include <gtest/gtest.h>

#include "bridge/material/material.h"
#include "bridge_test_support.h"
#include "synthetic_sweep.h"

namespace softglass::bridge {
namespace {

using testing::expect_contains;

// The fragment, read as macro will: docs/material-format.md's entries and rules.
TEST(Material, WritesTheDocumentedFragment) {
  const Material m = make_material(testing::exact_law({}), {0.78, 40e3, 1e-3, false});
  const std::string text = material_text(m, {"softglass bridge material (test)"});
  expect_contains(text, {"# softglass bridge material (test)\n", "subsection material", "tau_y",
                         "statistical", "interpolation", "valid for shear rates"});
  dealii::ParameterHandler prm;
  namespace P = dealii::Patterns;
  prm.enter_subsection("material");
  prm.declare_entry("model", "newtonian",
                    P::Selection("herschel-bulkley|bingham|power-law|newtonian"));
  for (const char* name :
       {"yield stress", "consistency", "flow index", "N1 yield", "N1 consistency", "N1 flow index",
        "N2 yield", "N2 consistency", "N2 flow index"})
    prm.declare_entry(name, "0", P::Double());
  prm.leave_subsection();
  prm.parse_input_from_string(text);
  prm.enter_subsection("material");
  EXPECT_EQ(prm.get("model"), "herschel-bulkley");
  EXPECT_NEAR(prm.get_double("yield stress"), m.laws[0]->yield.value,
              1e-5 * m.laws[0]->yield.value);
  EXPECT_GT(prm.get_double("consistency"), 0.0);
  EXPECT_GT(prm.get_double("flow index"), 0.0);
  EXPECT_LE(prm.get_double("flow index"), 2.0);
  EXPECT_LT(prm.get_double("N2 consistency"), 0.0);
  prm.leave_subsection();
}

}  // namespace
}  // namespace softglass::bridge
