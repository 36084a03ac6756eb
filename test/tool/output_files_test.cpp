#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "coverage_system/mission/pose_csv_reader.h"
#include "coverage_system/tool/json_object.h"
#include "coverage_system/tool/waypoint_csv_writer.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

std::string csvError(const std::string& text) {
  try {
    PoseCsvReader().parse(text, "f.csv");
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

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

TEST(PoseCsvReader, ReadsColumnsByName) {
  const PoseTable table = PoseCsvReader().parse(
      "kind, yaw ,t,extra,y,x\r\nsegment,4,0,a,2,1\r\n\r\nrotation,0.5,1.5,b,2,1\r\n", "f.csv");
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_TRUE(table.has_time);
  EXPECT_TRUE(table.has_kind);
  EXPECT_EQ(table.rows[0].pose.x, 1.0);
  EXPECT_EQ(table.rows[0].pose.y, 2.0);
  EXPECT_NEAR(table.rows[0].pose.yaw, 4 - 2 * M_PI, 1e-12);
  EXPECT_EQ(table.rows[1].t, 1.5);
  EXPECT_EQ(table.rows[1].kind, "rotation");
}

TEST(PoseCsvReader, NamesEveryProblem) {
  EXPECT_EQ(csvError("x,y\n1,2\n"),
            "f.csv:1: the header has no 'yaw' column (x, y and yaw are required)");
  EXPECT_EQ(csvError("x,y,yaw,x\n1,2,3,4\n"), "f.csv:1: the column 'x' appears twice");
  EXPECT_EQ(csvError("x,y,yaw\n1,2,3\n1,2\n"), "f.csv:3: 2 fields, but the header has 3");
  EXPECT_EQ(csvError("x,y,yaw\n1,abc,3\n"), "f.csv:2: column y: 'abc' is not a number");
  EXPECT_EQ(csvError("x,y,yaw\n1,2,\n"), "f.csv:2: column yaw: '' is not a number");
  EXPECT_EQ(csvError("x,y,yaw\n1,inf,3\n"), "f.csv:2: column y: 'inf' is not finite");
  EXPECT_EQ(csvError("x,y,yaw,kind\n1,2,3,Curve!\n"),
            "f.csv:2: column kind: 'Curve!' is not a kind name (segment, arc, rotation, "
            "clothoid, ...: lower-case letters, digits and underscores)");
  EXPECT_EQ(csvError("x,y,yaw,kind\n1,2,3,clothoid\n1,2,3,spline_2\n"), "");
  EXPECT_EQ(csvError("t,x,y,yaw\n2,1,2,3\n1,1,2,3\n"),
            "f.csv:3: column t: 1 is before the previous row's time");
  EXPECT_EQ(csvError(""), "f.csv: the file is empty (no header row)");
  EXPECT_EQ(csvError("x,y,yaw\n"), "f.csv: the file has no rows");
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
