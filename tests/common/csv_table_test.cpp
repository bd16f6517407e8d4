// The strict CSV reader: comments, header, quoting, line endings, and the
// refusal of missing or non-finite numbers with file, line and column named.
#include <gtest/gtest.h>

#include "common/csv_table.h"
#include "common/errors.h"
#include "tests/common/text_checks.h"

namespace softglass {
namespace {

using testing::expect_contains;

TEST(CsvTable, ReadsCommentsHeaderAndRows) {
  const CsvTable t = CsvTable::parse(
      "\xEF\xBB\xBF# made by hand\r\n#  second line\n\nphi [1], sigma [E*]\r\n0.8, "
      "1e-3\n\n0.85,+2.5E-3\n",
      "t.csv");
  ASSERT_EQ(t.comments().size(), 2u);
  EXPECT_EQ(t.comments()[0], "made by hand");
  EXPECT_EQ(t.header(), (std::vector<std::string>{"phi [1]", "sigma [E*]"}));
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.number(0, 1), 1e-3);
  EXPECT_EQ(t.number(1, 1), 2.5e-3);
  EXPECT_EQ(t.line(1), 7u) << "line numbers count blank and comment lines";
  EXPECT_EQ(t.find("sigma [E*]"), 1u);
  EXPECT_FALSE(t.find("sigma"));
}

TEST(CsvTable, QuotedCellsMayHoldCommasAndQuotes) {
  const CsvTable t = CsvTable::parse("name,x\n\"a, \"\"b\"\"\",1\n", "q.csv");
  EXPECT_EQ(t.text(0, 0), "a, \"b\"");
  EXPECT_THROW(CsvTable::parse("name,x\n\"open,1\n", "q.csv"), InputError);
}

TEST(CsvTable, RefusesMissingAndNonFiniteNumbersNamingTheCell) {
  const CsvTable t = CsvTable::parse("a [1],b [1]\n1,\n2,nan\n3,inf\n4,1.5x\n5,abc\n", "bad.csv");
  const std::pair<std::size_t, const char*> cases[] = {
      {0, "empty"}, {1, "not finite"}, {2, "not finite"}, {3, "not a number"}, {4, "not a number"}};
  for (const auto& [row, what] : cases) {
    try {
      t.number(row, 1);
      ADD_FAILURE() << "row " << row << " accepted";
    } catch (const InputError& e) {
      expect_contains(e.what(), {"bad.csv", "line " + std::to_string(row + 2), "'b [1]'", what});
    }
  }
}

TEST(CsvTable, RefusesRowsOfTheWrongLengthAndTablesWithoutHeader) {
  try {
    CsvTable::parse("a,b\n1,2\n3\n", "short.csv");
    ADD_FAILURE();
  } catch (const InputError& e) {
    expect_contains(e.what(), {"short.csv, line 3", "1 cells", "has 2"});
  }
  EXPECT_THROW(CsvTable::parse("# only a comment\n", "empty.csv"), InputError);
  EXPECT_THROW(CsvTable::read("/no/such/file.csv"), InputError);
}

TEST(CsvTable, SplitsUnitsFromColumnNames) {
  EXPECT_EQ(split_units("sigma [E*]").name, "sigma");
  EXPECT_EQ(split_units("sigma [E*]").units, "E*");
  EXPECT_EQ(split_units(" f_m [E* R^2] ").units, "E* R^2");
  EXPECT_EQ(split_units("Shear rate").units, "");
  EXPECT_EQ(split_units("Shear rate").name, "Shear rate");
}

}  // namespace
}  // namespace softglass
