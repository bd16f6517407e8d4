// Warnings of one kind folded into one line with a count and their places.
#include <gtest/gtest.h>

#include "common/warning_collector.h"

namespace softglass {
namespace {

TEST(WarningCollector, FoldsOneKindIntoOneLineWithACount) {
  WarningCollector w;
  EXPECT_TRUE(w.empty());
  w.add("poorly determined", "phi 0.7, N1");
  w.add("the fit failed", "phi 0.8, sigma");
  w.add("poorly determined", "phi 0.75, N1");
  w.add("poorly determined", "phi 0.8, N2");
  const std::vector<std::string> lines = w.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "poorly determined (3 times: phi 0.7, N1; phi 0.75, N1; phi 0.8, N2)");
  EXPECT_EQ(lines[1], "phi 0.8, sigma: the fit failed");
}

TEST(WarningCollector, NamesTheFirstPlacesAndCountsTheRest) {
  WarningCollector w;
  for (int i = 0; i < 5; ++i) w.add("slow", "run " + std::to_string(i));
  w.add("no place");
  w.add("no place");
  const std::vector<std::string> lines = w.lines(2);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "slow (5 times: run 0; run 1; and 3 more)");
  EXPECT_EQ(lines[1], "no place (2 times)");
}

}  // namespace
}  // namespace softglass
