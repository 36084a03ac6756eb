#include "coverage_system/mission/autopilot_mission.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A 40 m square with a 1 m square hole at the origin.
PolygonWithHoles squareWithHole() {
  return {{{-20, -20}, {20, -20}, {20, 20}, {-20, 20}}, {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}}};
}

VehicleLimits vehicle() {
  VehicleLimits limits;
  limits.v_max = 0.5;
  limits.yaw_rate_max = 0.25;
  limits.turning_radius = 1.0;
  return limits;
}

/// The least distance from the walls of the polyline through the waypoints.
double waypointPathClearance(const AutopilotMission& mission, const PolygonWithHoles& area) {
  double least = INFINITY;
  for (std::size_t i = 0; i + 1 < mission.waypoints.size(); ++i) {
    const Point2& a = mission.waypoints[i].position;
    const Point2& b = mission.waypoints[i + 1].position;
    for (int k = 0; k <= 200; ++k) {
      least = std::min(least, distanceToBoundary(a + (k / 200.0) * (b - a), area));
    }
  }
  return least;
}

TEST(AutopilotMission, SegmentEndsAreWaypointsAndSharpCornersAreHeld) {
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({-10, -10}, {-10, 10}),
                                           PathPrimitive::rotation({-10, 10}, M_PI / 2, -M_PI / 2),
                                           PathPrimitive::segment({-10, 10}, {10, 10})};
  const AutopilotMission mission =
      AutopilotMissionBuilder(vehicle(), 2.0).build(path, squareWithHole(), 1.0);
  ASSERT_EQ(mission.waypoints.size(), 3u);
  EXPECT_EQ(mission.waypoints[1].position, Point2(-10, 10));
  EXPECT_FALSE(mission.waypoints[0].hold);
  EXPECT_TRUE(mission.waypoints[1].hold);
  EXPECT_FALSE(mission.waypoints[2].hold);
  for (const AutopilotWaypoint& waypoint : mission.waypoints) EXPECT_EQ(waypoint.speed, 0.5);
}

TEST(AutopilotMission, ArcsBecomeWaypointsNearTheArcAtTheArcSpeed) {
  // A quarter turn of radius 4 about (-6, 6) between two legs, far from the hole.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({-10, -10}, {-10, 6}),
                                           PathPrimitive::arc({-6, 6}, 4.0, M_PI, -M_PI / 2),
                                           PathPrimitive::segment({-6, 10}, {10, 10})};
  const AutopilotMission mission =
      AutopilotMissionBuilder(vehicle(), 2.0).build(path, squareWithHole(), 1.0);
  // The quarter turn takes ceil((pi / 2) / kMaxTurnStep) = 4 steps.
  ASSERT_GE(mission.waypoints.size(), 2u + 4u);
  const double sagitta = 4.0 * (1.0 / std::cos(AutopilotMissionBuilder::kMaxTurnStep / 2) - 1.0);
  for (std::size_t i = 2; i + 1 < mission.waypoints.size(); ++i) {
    const double radius = (mission.waypoints[i].position - Point2(-6, 6)).norm();
    EXPECT_NEAR(radius, 4.0, sagitta + 1e-9);
    // On the arc: min(v_max, yaw_rate_max * r) = 0.25 * 4 = 1 > 0.5.
    EXPECT_DOUBLE_EQ(mission.waypoints[i].speed, 0.5);
    EXPECT_FALSE(mission.waypoints[i].hold);
  }
  EXPECT_EQ(mission.waypoints.back().position, Point2(10, 10));
}

TEST(AutopilotMission, AWaypointWhoseCutWouldComeNearAWallIsHeld) {
  // Past the hole's left side and over its top, 1 m from both: a corner at (-1, 2), 1.41 m
  // from the hole's corner (0, 1), which a 2 m cut would pass through.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({-1, -10}, {-1, 2}),
                                           PathPrimitive::segment({-1, 2}, {10, 2})};
  const PolygonWithHoles area = squareWithHole();
  const AutopilotMission cut = AutopilotMissionBuilder(vehicle(), 2.0).build(path, area, 1.0);
  ASSERT_EQ(cut.waypoints.size(), 3u);
  EXPECT_TRUE(cut.waypoints[1].hold);
  EXPECT_GE(cut.corner_cut_clearance_m, 1.0 - kClearanceTolerance);
  // A cut of 0.1 m keeps 1 m: nothing held.
  const AutopilotMission small = AutopilotMissionBuilder(vehicle(), 0.1).build(path, area, 1.0);
  EXPECT_FALSE(small.waypoints[1].hold);
  EXPECT_GE(small.corner_cut_clearance_m, 1.0 - kClearanceTolerance);
}

TEST(AutopilotMission, CurveWaypointsKeepTheCurvesClearance) {
  // Round the hole's corner (1, 1) at exactly 1 m: an arc about it, which inscribed
  // waypoints would cut into the hole's wall band, and then away from it.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({2, -10}, {2, 1}),
                                           PathPrimitive::arc({1, 1}, 1.0, 0.0, M_PI / 2),
                                           PathPrimitive::segment({1, 2}, {-10, 2})};
  const PolygonWithHoles area = squareWithHole();
  for (double radius : {0.0, 0.5, 2.0, 8.0}) {
    const AutopilotMission mission =
        AutopilotMissionBuilder(vehicle(), radius).build(path, area, 1.0);
    EXPECT_GE(waypointPathClearance(mission, area), 1.0 - kClearanceTolerance) << radius;
    EXPECT_GE(mission.corner_cut_clearance_m, 1.0 - kClearanceTolerance) << radius;
    // The arc's speed: yaw_rate_max * r = 0.25 m/s.
    EXPECT_DOUBLE_EQ(mission.waypoints[2].speed, 0.25);
  }
}

TEST(AutopilotMission, AStartInTheWallBandIsLeftOutOfTheClearance) {
  // From 0.2 m beside the hole's left side out to 1 m from it, then on.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({-0.2, 0.5}, {-1, 0.5}),
                                           PathPrimitive::segment({-1, 0.5}, {-1, -10})};
  const AutopilotMission mission =
      AutopilotMissionBuilder(vehicle(), 2.0).build(path, squareWithHole(), 1.0);
  EXPECT_GE(mission.corner_cut_clearance_m, 1.0 - kClearanceTolerance);
}

}  // namespace
}  // namespace kinematic_coverage::core
