// The flow-curve columns micro writes and bridge reads (common/flow_curve_columns.h):
// every column has the unit docs/flow-curve-format.md gives it, a quantity's
// parts and errors share its unit, and a name that only begins like a
// quantity is not taken for one.
#include <gtest/gtest.h>

#include "common/flow_curve_columns.h"

namespace softglass::flow_curve {
namespace {

TEST(FlowCurveColumns, EveryColumnHasItsDocumentedUnit) {
  for (const char* name : {phi, gamma_tilde, packings, seed, converged, coordination})
    EXPECT_EQ(unit_of(name), "1") << name;
  for (const char* name : stresses) {
    EXPECT_EQ(unit_of(name), "E*") << name;
    EXPECT_EQ(unit_of(error_of(name)), "E*") << name;
  }
  EXPECT_EQ(unit_of(error_of(shear_modulus)), "E*");
  EXPECT_EQ(unit_of(error_of(contact_force)), "E*R^2");
  EXPECT_EQ(unit_of(error_of(contact_distance)), "R");
}

TEST(FlowCurveColumns, AnUnknownNameHasNoUnit) {
  for (const char* name : {"sigmax", "N12", "G", "f", "temperature", ""})
    EXPECT_EQ(unit_of(name), "") << name;
}

}  // namespace
}  // namespace softglass::flow_curve
