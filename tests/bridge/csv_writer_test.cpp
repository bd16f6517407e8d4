// bridge's result tables: a cell that does not apply is written `nan`, an
// infinity is never written.
#include <gtest/gtest.h>

#include <cmath>

#include "bridge/output/csv_writer.h"
#include "common/errors.h"

namespace softglass::bridge {
namespace {

TEST(CsvWriter, WritesNotApplicableCellsAndRefusesInfinity) {
  CsvWriter w({"made by a test"}, {"phi [1]", "yield [E*]"});
  w << 0.8 << NAN;
  w.end_row();
  EXPECT_EQ(w.text(), "# made by a test\nphi [1],yield [E*]\n0.8,nan\n");
  CsvWriter bad({}, {"phi [1]", "yield [E*]"});
  bad << 0.8;
  try {
    bad << -INFINITY;
    ADD_FAILURE() << "an infinity was written";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("column 2 (of 2) came out as -inf"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace softglass::bridge
