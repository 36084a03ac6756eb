#include "trajectory_generation_tools/path/path_primitive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

TEST(PathPrimitive, ClothoidPointsAreTheFresnelIntegrals) {
  // The standard clothoid (curvature pi s) reaches (C(1), S(1)) after 1 m, the Fresnel
  // integrals' tabulated values, heading pi / 2 and curvature pi.
  const PathPrimitive clothoid = PathPrimitive::clothoid({0, 0, 0}, 0.0, M_PI, 1.0);
  EXPECT_EQ(clothoid.kind(), PrimitiveKind::kClothoid);
  EXPECT_NEAR(clothoid.end().x(), 0.7798934003768228, 1e-12);
  EXPECT_NEAR(clothoid.end().y(), 0.4382591473903548, 1e-12);
  EXPECT_NEAR(clothoid.endPose().yaw, M_PI / 2, 1e-15);
  EXPECT_DOUBLE_EQ(clothoid.length(), 1.0);
  EXPECT_NEAR(clothoid.turnAngle(), M_PI / 2, 1e-15);
  EXPECT_NEAR(clothoid.curvature(), M_PI, 1e-15);
  EXPECT_NEAR(clothoid.curvatureAt(0.5), M_PI / 2, 1e-15);
  EXPECT_DOUBLE_EQ(clothoid.radius(), 1.0 / M_PI);
  // Its poses agree with its end, and at half its length with the half-length clothoid.
  EXPECT_TRUE(clothoid.poseAt(1.0).position().isApprox(clothoid.end(), 1e-15));
  const PathPrimitive half = PathPrimitive::clothoid({0, 0, 0}, 0.0, M_PI, 0.5);
  EXPECT_LT((clothoid.poseAt(0.5).position() - half.end()).norm(), 1e-13);
}

TEST(PathPrimitive, AClothoidOfConstantCurvatureIsAnArcAndOfNoneASegment) {
  const PathPrimitive arc_like = PathPrimitive::clothoid({1, 2, 0.3}, -0.5, 0.0, 2.0);
  const PathPrimitive arc = PathPrimitive::arc(
      Point2(1, 2) + 2.0 * Point2(std::sin(0.3), -std::cos(0.3)), 2.0, 0.3 + M_PI / 2, -1.0);
  EXPECT_LT((arc_like.end() - arc.end()).norm(), 1e-12);
  EXPECT_NEAR(arc_like.endPose().yaw, arc.endPose().yaw, 1e-15);
  const PathPrimitive straight = PathPrimitive::clothoid({1, 2, 0.3}, 0.0, 0.0, 2.0);
  EXPECT_LT((straight.end() - Point2(1 + 2 * std::cos(0.3), 2 + 2 * std::sin(0.3))).norm(), 1e-15);
  EXPECT_EQ(straight.curvature(), 0.0);
  EXPECT_TRUE(std::isinf(straight.radius()));
}

TEST(PathPrimitive, PolylinesStayWithinTheirTolerance) {
  for (const PathPrimitive& curve : {PathPrimitive::clothoid({0, 0, 1.0}, 0.2, -1.7, 3.0),
                                     PathPrimitive::arc({1, 1}, 0.4, 0.5, 4.0)}) {
    for (const double tolerance : {1e-2, 1e-4}) {
      const std::vector<Point2> chords = curve.polyline(tolerance);
      ASSERT_GE(chords.size(), 2u);
      EXPECT_EQ(chords.front(), curve.start());
      EXPECT_EQ(chords.back(), curve.end());
      for (int k = 0; k <= 1000; ++k) {
        const Point2 p = curve.poseAt(k / 1000.0).position();
        double nearest = 1e9;
        for (std::size_t i = 1; i < chords.size(); ++i) {
          const Point2 d = chords[i] - chords[i - 1];
          const double t = std::clamp((p - chords[i - 1]).dot(d) / d.squaredNorm(), 0.0, 1.0);
          nearest = std::min(nearest, (p - chords[i - 1] - t * d).norm());
        }
        EXPECT_LE(nearest, tolerance) << k;
      }
    }
  }
  EXPECT_EQ(PathPrimitive::segment({0, 0}, {3, 4}).polyline(1e-3).size(), 2u);
  EXPECT_EQ(PathPrimitive::rotation({0, 0}, 0.0, 1.0).polyline(1e-3).size(), 1u);
}

}  // namespace
}  // namespace kinematic_coverage::core
