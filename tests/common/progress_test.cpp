// The time left of a progress line: extrapolated from the work done since the
// clock started, so that resumed work does not make a long task look short.
#include "common/progress.h"

#include <gtest/gtest.h>

#include <cmath>

namespace softglass {
namespace {

TEST(Progress, TimeLeftExtrapolatesTheRateSoFar) {
  EXPECT_DOUBLE_EQ(time_left(10.0, 0.25, 1.0), 30.0);
  EXPECT_DOUBLE_EQ(time_left(10.0, 1.0, 1.0), 0.0);
  EXPECT_TRUE(std::isnan(time_left(10.0, 0.0, 1.0))) << "nothing done yet: unknown";
}

// A task resumed at 40 % that reaches 50 % in 10 s has done 10 % in 10 s: 50 s
// left, not the 10 s the 50 % alone would suggest.
TEST(Progress, WorkCarriedFromBeforeDoesNotCountTowardsTheRate) {
  EXPECT_DOUBLE_EQ(time_left(10.0, 0.5, 1.0, 0.4), 50.0);
  EXPECT_TRUE(std::isnan(time_left(1.0, 0.4, 1.0, 0.4))) << "no progress since the resume";
}

TEST(Progress, DurationsReadAsTimes) {
  EXPECT_EQ(format_duration(12.44), "12.4s");
  EXPECT_EQ(format_duration(185.0), "3m05s");
  EXPECT_EQ(format_duration(3720.0), "1h02m");
  EXPECT_EQ(format_duration(NAN), "?");
}

}  // namespace
}  // namespace softglass
