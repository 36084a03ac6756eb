#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace kinematic_coverage::core {
namespace {

PolygonWithHoles squareWithHole() {
  return {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
}

TEST(PlanarGeometry, AreaOfSquareWithHole) {
  EXPECT_DOUBLE_EQ(area(squareWithHole()), 96.0);
  EXPECT_GT(signedArea(squareWithHole().hull), 0.0);
  EXPECT_LT(signedArea(squareWithHole().holes[0]), 0.0);
}

TEST(PlanarGeometry, CentroidOfAreasWithHolesAndEitherOrientation) {
  PolygonWithHoles square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  EXPECT_NEAR((centroid(square) - Point2(2, 2)).norm(), 0.0, 1e-12);
  // Clockwise, far from the origin: the same centroid.
  PolygonWithHoles far{{{1e6, 1e6}, {1e6, 1e6 + 4}, {1e6 + 4, 1e6 + 4}, {1e6 + 4, 1e6}}, {}};
  EXPECT_NEAR((centroid(far) - Point2(1e6 + 2, 1e6 + 2)).norm(), 0.0, 1e-9);
  // A 4 x 4 square less its right 2 x 4 half as a hole: the left half's centre (1, 2).
  square.holes = {{{2, 0}, {2, 4}, {4, 4}, {4, 0}}};
  EXPECT_NEAR((centroid(square) - Point2(1, 2)).norm(), 0.0, 1e-12);
  // A degenerate hull: its first vertex.
  EXPECT_EQ(centroid(PolygonWithHoles{{{3, 1}, {3, 1}, {3, 1}}, {}}), Point2(3, 1));
}

TEST(PlanarGeometry, LegHeadingPosesFaceAlongTheLegLeavingThem) {
  const std::vector<Pose2> poses = legHeadingPoses({{0, 0}, {1, 0}, {1, 2}, {-1, 2}});
  ASSERT_EQ(poses.size(), 4u);
  EXPECT_DOUBLE_EQ(poses[0].yaw, 0.0);
  EXPECT_DOUBLE_EQ(poses[1].yaw, M_PI / 2);
  EXPECT_DOUBLE_EQ(poses[2].yaw, M_PI);
  EXPECT_DOUBLE_EQ(poses[3].yaw, M_PI);  // the last faces along the leg reaching it
  EXPECT_EQ(poses[2].position(), Point2(1, 2));
  EXPECT_DOUBLE_EQ(legHeadingPoses({{3, 4}}).front().yaw, 0.0);
  EXPECT_TRUE(legHeadingPoses({}).empty());
}

TEST(PlanarGeometry, ContainsRespectsHoles) {
  const PolygonWithHoles polygon = squareWithHole();
  EXPECT_TRUE(contains(polygon, {1, 1}));
  EXPECT_FALSE(contains(polygon, {5, 5}));
  EXPECT_FALSE(contains(polygon, {11, 5}));
  EXPECT_TRUE(contains(polygon, {10.0 + 1e-8, 5}, 1e-6));
}

TEST(PlanarGeometry, SegmentInsideDetectsHoleCrossing) {
  const PolygonWithHoles polygon = squareWithHole();
  EXPECT_TRUE(segmentInside(polygon, {1, 1}, {9, 1}));
  EXPECT_FALSE(segmentInside(polygon, {1, 5}, {9, 5}));
  // Along the hole's edge: touching is inside.
  EXPECT_TRUE(segmentInside(polygon, {4, 1}, {4, 9}));
  // Along the hull's boundary.
  EXPECT_TRUE(segmentInside(polygon, {0, 0}, {10, 0}));
  EXPECT_FALSE(segmentInside(polygon, {-1, 5}, {5, 2}));
}

TEST(PlanarGeometry, WrapAngleIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrapAngle(-M_PI), M_PI);
  EXPECT_DOUBLE_EQ(wrapAngle(3 * M_PI), M_PI);
  EXPECT_NEAR(wrapAngle(2 * M_PI + 0.5), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(headingOf({0, 0}, {-1, 0}), M_PI);
}

TEST(PlanarGeometry, DistanceToSegmentDegenerate) {
  EXPECT_DOUBLE_EQ(distanceToSegment({3, 4}, {0, 0}, {0, 0}), 5.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({5, 3}, {0, 0}, {10, 0}), 3.0);
}

}  // namespace
}  // namespace kinematic_coverage::core
