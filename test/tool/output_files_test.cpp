#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "coverage_system/mission/pose_csv_reader.h"
#include "coverage_system/tool/json_object.h"
#include "coverage_system/tool/waypoint_csv_writer.h"

namespace kinematic_coverage::core {
namespace {

TEST(WaypointCsvWriter, WritesHeaderAndWrappedYaw) {
  const std::string text =
      WaypointCsvWriter().format({{0.1, -2, 0.5}, {3, 4, 3 * M_PI / 2}, {5, 6, -M_PI}});
  EXPECT_EQ(text, "x,y,yaw\n0.1,-2,0.5\n3,4,-1.5707963267948966\n5,6,3.141592653589793\n");
  EXPECT_THROW(WaypointCsvWriter().format({{std::nan(""), 0, 0}}), std::domain_error);
}

TEST(PoseCsv, RoundTripsRandomPosesExactly) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-1e4, 1e4);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::vector<Pose2> poses(500);
  for (Pose2& pose : poses) pose = {value(rng), value(rng), angle(rng)};
  const PoseTable table = PoseCsvReader().parse(WaypointCsvWriter().format(poses), "w.csv");
  ASSERT_EQ(table.rows.size(), poses.size());
  EXPECT_FALSE(table.has_time);
  EXPECT_FALSE(table.has_kind);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(table.rows[i].pose.x, poses[i].x);
    EXPECT_EQ(table.rows[i].pose.y, poses[i].y);
    EXPECT_EQ(table.rows[i].pose.yaw, poses[i].yaw);
  }
}

TEST(JsonObject, WritesNumbersAndNestedObjects) {
  JsonObject percentiles;
  percentiles.set("50", 0.25).set("99", 1.5);
  JsonObject metrics;
  metrics.set("cells", 7).set("planning_time_s", 0.1).set("percentiles", percentiles);
  metrics.set("cells", 8);
  EXPECT_TRUE(metrics.has("cells"));
  EXPECT_FALSE(metrics.has("x"));
  EXPECT_EQ(
      metrics.toString(),
      "{\"cells\": 8, \"planning_time_s\": 0.1, \"percentiles\": {\"50\": 0.25, \"99\": 1.5}}");
}

TEST(JsonObject, EscapesKeysAndRejectsNonFiniteNumbers) {
  JsonObject object;
  object.set("a\"b\\c\nd\x01", -1e-300);
  EXPECT_EQ(object.toString(), "{\"a\\\"b\\\\c\\nd\\u0001\": -1e-300}");
  EXPECT_THROW(object.set("x", std::numeric_limits<double>::infinity()), std::domain_error);
  EXPECT_THROW(object.set("x", std::nan("")), std::domain_error);
}

}  // namespace
}  // namespace kinematic_coverage::core
