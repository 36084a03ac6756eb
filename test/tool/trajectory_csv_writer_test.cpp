#include "coverage_system/tool/trajectory_csv_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/trajectory/segment_path_builder.h"
#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"
#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

namespace kinematic_coverage::core {
namespace {

TrajectoryPose pose(double t, double x, double y, double yaw, PrimitiveKind kind) {
  TrajectoryPose p;
  p.t = t;
  p.x = x;
  p.y = y;
  p.yaw = yaw;
  p.kind = kind;
  return p;
}

TEST(TrajectoryCsvWriter, HeaderRowsAndKinds) {
  const std::string text =
      TrajectoryCsvWriter().format({pose(0, 0.1, -2, 0.5, PrimitiveKind::kSegment),
                                    pose(1.5, 3, 4, 3 * M_PI / 2, PrimitiveKind::kArc),
                                    pose(2, 3, 4, -M_PI, PrimitiveKind::kRotation),
                                    pose(3, 5, 4, 0.25, PrimitiveKind::kClothoid)});
  EXPECT_EQ(text,
            "t,x,y,yaw,kind\n0,0.1,-2,0.5,segment\n1.5,3,4,-1.5707963267948966,arc\n"
            "2,3,4,3.141592653589793,rotation\n3,5,4,0.25,clothoid\n");
  EXPECT_EQ(TrajectoryCsvWriter().format({}), "t,x,y,yaw,kind\n");
  EXPECT_THROW(TrajectoryCsvWriter().format({pose(std::nan(""), 0, 0, 0, PrimitiveKind::kArc)}),
               std::domain_error);
}

TEST(TrajectoryCsvWriter, NumbersReadBackExactly) {
  const std::vector<PathPrimitive> path = SegmentPathBuilder().build(
      std::vector<Point2>{{0.1, 0.7}, {13.3, 2.9}, {4.4, -8.1}, {1.0 / 3.0, 5}});
  std::vector<TrajectoryPose> poses = TrajectorySampler(0.37, 0.1, 0.3).sample(path);
  TrajectoryTiming(0.5, 0.2, 0.5).assignTimes(path, poses);
  const std::string file = ::testing::TempDir() + "trajectory_csv_writer_test.csv";
  TrajectoryCsvWriter().write(file, poses);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,x,y,yaw,kind");
  std::size_t row = 0;
  while (std::getline(in, line)) {
    ASSERT_LT(row, poses.size());
    std::stringstream fields(line);
    std::string t, x, y, yaw, kind;
    std::getline(fields, t, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, yaw, ',');
    std::getline(fields, kind, ',');
    EXPECT_EQ(std::strtod(t.c_str(), nullptr), poses[row].t);
    EXPECT_EQ(std::strtod(x.c_str(), nullptr), poses[row].x);
    EXPECT_EQ(std::strtod(y.c_str(), nullptr), poses[row].y);
    EXPECT_EQ(std::strtod(yaw.c_str(), nullptr), poses[row].yaw);
    EXPECT_EQ(kind, TrajectoryCsvWriter::kindName(poses[row].kind));
    ++row;
  }
  EXPECT_EQ(row, poses.size());
  std::remove(file.c_str());
}

TEST(TrajectoryCsvWriter, UnwritableFileIsInvalidInput) {
  EXPECT_THROW(TrajectoryCsvWriter().write("/nonexistent-dir/trajectory.csv", {}),
               InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
