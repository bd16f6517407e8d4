// The slip-law fragment `bridge slip-law` writes, read as macro reads
// `subsection slip` (macro/material/slip_parameters.cpp): with deal.II's
// ParameterHandler and the same entries.
#include <deal.II/base/parameter_handler.h>
#include <gtest/gtest.h>

#include "bridge/slip/slip_law.h"
#include "bridge_test_support.h"

namespace softglass::bridge {
namespace {

TEST(SlipLaw, WritesTheSlipSubsectionMacroReads) {
  const std::string text = slip_law_text({"softglass bridge slip-law (test)", "beta ~ R"},
                                         3.25e-7, 1.92);
  testing::expect_contains(text, {"# softglass bridge slip-law (test)\n", "# beta ~ R\n"});
  dealii::ParameterHandler prm;
  namespace P = dealii::Patterns;
  prm.enter_subsection("slip");
  prm.declare_entry("law", "power-law", P::Selection("power-law"));
  for (const char* name : {"coefficient", "exponent", "yield stress"})
    prm.declare_entry(name, "0", P::Double());
  prm.leave_subsection();
  prm.parse_input_from_string(text);
  prm.enter_subsection("slip");
  EXPECT_EQ(prm.get("law"), "power-law");
  EXPECT_DOUBLE_EQ(prm.get_double("coefficient"), 3.25e-7);
  EXPECT_DOUBLE_EQ(prm.get_double("exponent"), 1.92);
  EXPECT_EQ(prm.get_double("yield stress"), 0.0);
  prm.leave_subsection();
}

}  // namespace
}  // namespace softglass::bridge
