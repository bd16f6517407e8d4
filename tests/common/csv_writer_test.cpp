// The one CSV form of the tools' result tables: the header first, then the
// units and comment lines, then the rows; CsvTable reads it back with its
// units; a cell that does not apply is `nan` only where a column may be n/a,
// an infinity is never written, a standard error never negative.
#include <gtest/gtest.h>

#include <cmath>

#include "common/csv_table.h"
#include "common/csv_writer.h"
#include "common/errors.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {


TEST(CsvWriter, WritesTheHeaderFirstThenUnitsCommentsAndRows) {
  CsvWriter w("t.csv", {"curve", "phi [1]", "yield [E*]", "yield_se [E*]"}, {"made by a test"});
  w << std::string("A, first") << 0.8 << 1.5e-3 << NAN;
  w.end_row();
  EXPECT_EQ(w.text(),
            "curve,phi,yield,yield_se\n# units: ,1,E*,E*\n# made by a test\n"
            "\"A, first\",0.8,0.0015,nan\n");
  const CsvTable back = CsvTable::parse(w.text(), "t.csv");
  EXPECT_EQ(back.header(),
            (std::vector<std::string>{"curve", "phi [1]", "yield [E*]", "yield_se [E*]"}));
  EXPECT_EQ(back.comments(), std::vector<std::string>{"made by a test"});
  EXPECT_EQ(back.text(0, 0), "A, first");
  EXPECT_EQ(back.number(0, 2), 1.5e-3);
}

TEST(CsvWriter, RefusesNumbersWithoutMeaningNamingRowAndColumn) {
  const std::vector<std::string> header = {"phi [1]", "yield [E*]", "yield_se [E*]"};
  for (const double bad : {NAN, INFINITY, -INFINITY}) {
    EXPECT_NE(testing::refusal_of<NumericalError>([&] {
                CsvWriter("t.csv", header, {}) << 0.8 << bad;
              }).find("t.csv: row 1, column 'yield' came out as"),
              std::string::npos)
        << bad;
  }
  EXPECT_NE(testing::refusal_of<NumericalError>([&] {
              CsvWriter("t.csv", header, {}) << 0.8 << 1.0 << INFINITY;
            }).find("column 'yield_se'"),
            std::string::npos);
  EXPECT_NE(testing::refusal_of<NumericalError>([&] {
              CsvWriter("t.csv", header, {}) << 0.8 << 1.0 << -1e-3;
            }).find("a standard error is not negative"),
            std::string::npos);
  CsvWriter declared("t.csv", header, {});
  declared.may_be_na("yield");
  declared << 0.8 << NAN << NAN;
  declared.end_row();
  EXPECT_TRUE(declared.text().ends_with("0.8,nan,nan\n"));
}

TEST(CsvWriter, AUnitsLineThatDoesNotFitTheHeaderIsRefused) {
  EXPECT_THROW(CsvTable::parse("a,b\n# units: 1\n1,2\n", "u.csv"), InputError);
  EXPECT_THROW(CsvTable::parse("a [1],b\n# units: 1,Pa\n1,2\n", "u.csv"), InputError);
  EXPECT_EQ(CsvTable::parse("a [1],b\n# units: ,Pa\n1,2\n", "u.csv").header(),
            (std::vector<std::string>{"a [1]", "b [Pa]"}));
}

}  // namespace
}  // namespace softglass
