#include "coverage_system/mission/pose_csv_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

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

TEST(PoseCsvReader, ReadsThePosesOfAFileInOrder) {
  const std::string path = testing::TempDir() + "pose_csv_reader_poses.csv";
  {
    std::ofstream file(path);
    file << "t,x,y,yaw\n0,1,2,0.5\n1,3,4,7\n";
  }
  const std::vector<Pose2> poses = PoseCsvReader().readPoses(path);
  std::remove(path.c_str());
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].x, 1.0);
  EXPECT_EQ(poses[0].y, 2.0);
  EXPECT_EQ(poses[0].yaw, 0.5);
  EXPECT_EQ(poses[1].x, 3.0);
  EXPECT_NEAR(poses[1].yaw, 7 - 2 * M_PI, 1e-12);
  EXPECT_THROW(PoseCsvReader().readPoses(path), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
