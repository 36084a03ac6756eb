#include "polygon_coverage_ros_bridge/base/number_format.h"

#include <gtest/gtest.h>

#include <cmath>

namespace kinematic_coverage::core {
namespace {

TEST(NumberFormat, LengthsReadInMetresOrKilometres) {
  EXPECT_EQ(formatLength(190.817), "190.8 m");
  EXPECT_EQ(formatLength(999.96), "1.00 km");
  EXPECT_EQ(formatLength(11740.1), "11.74 km");
}

TEST(NumberFormat, DurationsReadInTheUnitsOfTheirSize) {
  EXPECT_EQ(formatDuration(0.0), "0.0 s");
  EXPECT_EQ(formatDuration(42.46), "42.5 s");
  EXPECT_EQ(formatDuration(59.96), "1 min 00 s");
  EXPECT_EQ(formatDuration(391.0), "6 min 31 s");
  EXPECT_EQ(formatDuration(365.4), "6 min 05 s");
  EXPECT_EQ(formatDuration(3599.4), "59 min 59 s");
  EXPECT_EQ(formatDuration(3599.6), "1 h 00 min");
  EXPECT_EQ(formatDuration(11220.0), "3 h 07 min");
  // 674 900 s, a lake's survey: 7 d 19 h 28 min, not "6.749e+05 s".
  EXPECT_EQ(formatDuration(674900.0), "7 d 19 h 28 min");
  EXPECT_EQ(formatDuration(2 * 86400.0 + 14 * 3600.0 + 5 * 60.0), "2 d 14 h 05 min");
  EXPECT_EQ(formatDuration(-1.0), "-1 s");
  EXPECT_EQ(formatDuration(NAN), "nan s");
}

}  // namespace
}  // namespace kinematic_coverage::core
