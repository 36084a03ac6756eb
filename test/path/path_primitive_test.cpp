#include "trajectory_generation_tools/path/path_primitive.h"

#include <gtest/gtest.h>

#include <cmath>

namespace kinematic_coverage::core {
namespace {

TEST(PathPrimitive, SegmentLengthAndPoses) {
  const PathPrimitive segment = PathPrimitive::segment({1, 1}, {4, 5});
  EXPECT_EQ(segment.kind(), PrimitiveKind::kSegment);
  EXPECT_DOUBLE_EQ(segment.length(), 5.0);
  EXPECT_DOUBLE_EQ(segment.curvature(), 0.0);
  const Pose2 middle = segment.poseAt(0.5);
  EXPECT_DOUBLE_EQ(middle.x, 2.5);
  EXPECT_DOUBLE_EQ(middle.y, 3.0);
  EXPECT_NEAR(middle.yaw, std::atan2(4.0, 3.0), 1e-15);
}

TEST(PathPrimitive, CounterClockwiseArcHeadsAlongTheTangent) {
  const PathPrimitive arc = PathPrimitive::arc({0, 0}, 2.0, 0.0, M_PI / 2);
  EXPECT_NEAR(arc.length(), M_PI, 1e-15);
  EXPECT_DOUBLE_EQ(arc.curvature(), 0.5);
  EXPECT_NEAR(arc.startPose().x, 2.0, 1e-15);
  EXPECT_NEAR(arc.startPose().yaw, M_PI / 2, 1e-15);
  EXPECT_NEAR(arc.endPose().x, 0.0, 1e-15);
  EXPECT_NEAR(arc.endPose().y, 2.0, 1e-15);
  EXPECT_NEAR(arc.endPose().yaw, M_PI, 1e-15);
  EXPECT_TRUE(arc.end().isApprox(Point2(0, 2), 1e-15));
}

TEST(PathPrimitive, ClockwiseArcAndWrappedYaw) {
  const PathPrimitive arc = PathPrimitive::arc({0, 0}, 1.0, M_PI / 2, -M_PI);
  EXPECT_NEAR(arc.startPose().yaw, 0.0, 1e-15);
  EXPECT_NEAR(arc.endPose().y, -1.0, 1e-15);
  EXPECT_NEAR(std::abs(arc.endPose().yaw), M_PI, 1e-15);
  EXPECT_DOUBLE_EQ(arc.turnAngle(), M_PI);
}

TEST(PathPrimitive, RotationTurnsOnTheSpot) {
  const PathPrimitive rotation = PathPrimitive::rotation({3, 4}, 3.0, 0.5);
  EXPECT_DOUBLE_EQ(rotation.length(), 0.0);
  EXPECT_DOUBLE_EQ(rotation.turnAngle(), 0.5);
  const Pose2 end = rotation.endPose();
  EXPECT_DOUBLE_EQ(end.x, 3.0);
  EXPECT_NEAR(end.yaw, 3.5 - 2 * M_PI, 1e-15);
  EXPECT_EQ(PathPrimitive::segment({0, 0}, {1, 0}).withVariant(SmoothingVariant::kInner).variant(),
            SmoothingVariant::kInner);
}

}  // namespace
}  // namespace kinematic_coverage::core
