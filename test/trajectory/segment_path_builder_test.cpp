#include "trajectory_generation_tools/trajectory/segment_path_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

std::vector<PathPrimitive> build(const std::vector<Point2>& waypoints) {
  return SegmentPathBuilder().build(waypoints);
}

TEST(SegmentPathBuilder, RotatesTheShorterWayAtEveryBend) {
  const std::vector<PathPrimitive> path = build({{0, 0}, {2, 0}, {2, -3}, {5, -3}});
  ASSERT_EQ(path.size(), 5u);
  EXPECT_EQ(path[0].kind(), PrimitiveKind::kSegment);
  EXPECT_EQ(path[1].kind(), PrimitiveKind::kRotation);
  EXPECT_EQ(path[1].start(), Point2(2, 0));
  EXPECT_NEAR(path[1].startPose().yaw, 0.0, 1e-15);
  EXPECT_NEAR(path[1].sweep(), -M_PI_2, 1e-15);  // right turn, clockwise
  EXPECT_NEAR(path[1].endPose().yaw, -M_PI_2, 1e-15);
  EXPECT_NEAR(path[3].sweep(), M_PI_2, 1e-15);
  EXPECT_EQ(path[4].end(), Point2(5, -3));
}

TEST(SegmentPathBuilder, CollinearWaypointsNeedNoRotation) {
  const std::vector<PathPrimitive> path = build({{0, 0}, {1, 1}, {2, 2}, {3.5, 3.5}});
  ASSERT_EQ(path.size(), 3u);
  for (const PathPrimitive& primitive : path) EXPECT_EQ(primitive.kind(), PrimitiveKind::kSegment);
}

TEST(SegmentPathBuilder, DropsDuplicateWaypoints) {
  const std::vector<PathPrimitive> path =
      build({{0, 0}, {0, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 1}});
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[0].kind(), PrimitiveKind::kSegment);
  EXPECT_EQ(path[1].kind(), PrimitiveKind::kRotation);
  EXPECT_EQ(path[2].kind(), PrimitiveKind::kSegment);
  for (const PathPrimitive& primitive : path) {
    if (primitive.kind() == PrimitiveKind::kSegment) EXPECT_GT(primitive.length(), 0.0);
  }
}

TEST(SegmentPathBuilder, FullReversalTurnsPi) {
  const std::vector<PathPrimitive> path = build({{0, 0}, {3, 0}, {1, 0}});
  ASSERT_EQ(path.size(), 3u);
  EXPECT_NEAR(path[1].turnAngle(), M_PI, 1e-15);
  EXPECT_NEAR(std::abs(wrapAngle(path[1].endPose().yaw - path[2].startPose().yaw)), 0.0, 1e-15);
  // Nearly reversed either side: the shorter way round.
  const std::vector<PathPrimitive> left = build({{0, 0}, {3, 0}, {1, 1e-3}});
  const std::vector<PathPrimitive> right = build({{0, 0}, {3, 0}, {1, -1e-3}});
  EXPECT_GT(left[1].sweep(), 0.0);
  EXPECT_LT(left[1].sweep(), M_PI);
  EXPECT_LT(right[1].sweep(), 0.0);
  EXPECT_GT(right[1].sweep(), -M_PI);
}

TEST(SegmentPathBuilder, FewWaypoints) {
  EXPECT_TRUE(build({}).empty());
  const std::vector<PathPrimitive> single =
      SegmentPathBuilder().build(std::vector<Pose2>{{1, 2, 0.7}});
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].kind(), PrimitiveKind::kRotation);
  EXPECT_EQ(single[0].turnAngle(), 0.0);
  EXPECT_EQ(single[0].startPose().yaw, 0.7);
  EXPECT_EQ(build({{1, 2}, {1, 2}}).size(), 1u);
  const std::vector<PathPrimitive> two = build({{1, 2}, {4, 6}});
  ASSERT_EQ(two.size(), 1u);
  EXPECT_DOUBLE_EQ(two[0].length(), 5.0);
}

TEST(SegmentPathBuilder, RandomPathsAreContinuousWithHeadingsMatched) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coordinate(-5, 5);  // many collinear and repeated points
  for (int trial = 0; trial < 1000; ++trial) {
    std::vector<Point2> waypoints;
    for (int i = 0; i < 1 + trial % 10; ++i)
      waypoints.emplace_back(coordinate(rng), coordinate(rng));
    const std::vector<PathPrimitive> path = build(waypoints);
    ASSERT_FALSE(path.empty());
    for (std::size_t i = 1; i < path.size(); ++i) {
      EXPECT_EQ(path[i].start(), path[i - 1].end());
      EXPECT_FALSE(path[i].kind() == PrimitiveKind::kRotation &&
                   path[i - 1].kind() == PrimitiveKind::kRotation);
      if (path[i].kind() == PrimitiveKind::kRotation) {
        EXPECT_GT(path[i].turnAngle(), SegmentPathBuilder::kCollinearTolerance);
        EXPECT_LE(path[i].turnAngle(), M_PI);
      }
      if (path.size() > 1) {
        // Headings continue across every joint (a rotation takes the robot round).
        EXPECT_NEAR(wrapAngle(path[i].startPose().yaw - path[i - 1].endPose().yaw), 0.0, 1e-12)
            << trial;
      }
    }
  }
}

TEST(SegmentPathBuilder, RejectsNonFiniteWaypoints) {
  EXPECT_THROW(build({{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}}), InvalidInputError);
  EXPECT_THROW(build({{std::numeric_limits<double>::infinity(), 0}}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
