// Every number a tool writes through UnitTable is finite, or NaN in an error
// column, where it means n/a; anything else is refused naming row and column
// (common/csv_writer.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/errors.h"
#include "common/unit_table.h"
#include "tests/common/test_files.h"

namespace softglass {
namespace {

TEST(UnitTable, WritesFiniteCellsAndNotApplicableErrorsOnly) {
  testing::TemporaryDirectory dir;
  UnitTable table{{{"gamma0", "1"}, {"storage", "Pa"}, {"storage_se", "Pa"}}, {{1e-3, 120.5, NAN}}};
  write_csv(dir / "t.csv", dir / "t.csv", {}, table, 6);
  EXPECT_EQ(testing::read_text(dir / "t.csv"),
            "gamma0,storage,storage_se\n# units: 1,Pa,Pa\n0.001,120.5,nan\n");
  for (const double bad : {NAN, INFINITY}) {
    UnitTable wrong = table;
    wrong.rows.push_back({1e-2, bad, 1.0});
    try {
      write_csv(dir / "w.csv", dir / "w.csv", {}, wrong, 6);
      ADD_FAILURE() << bad << " written in a value column";
    } catch (const NumericalError& e) {
      EXPECT_NE(std::string(e.what()).find("row 2, column 'storage'"), std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "w.csv"));
  }
  UnitTable infinite_error = table;
  infinite_error.rows[0][2] = INFINITY;
  EXPECT_THROW(write_csv(dir / "e.csv", dir / "e.csv", {}, infinite_error, 6), NumericalError);
}

}  // namespace
}  // namespace softglass
