#include "test/planner/plan_properties.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "test/support/sampled_wall_distance.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {
namespace {

/// The length of the area's hull and holes.
double boundaryLength(const PolygonWithHoles& area) {
  double length = 0.0;
  auto add = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      length += (ring[(i + 1) % ring.size()] - ring[i]).norm();
  };
  add(area.hull);
  for (const Ring& hole : area.holes) add(hole);
  return length;
}

}  // namespace

void expectValidPlan(const PolygonWithHoles& free_area, const CoveragePlan& plan,
                     const PlannerParameters& parameters, const Point2& start, const Point2& goal) {
  const auto& waypoints = plan.waypoints;
  ASSERT_GE(waypoints.size(), 2u);
  EXPECT_NEAR((waypoints.front().position() - start).norm(), 0.0, 1e-9);
  EXPECT_NEAR((waypoints.back().position() - goal).norm(), 0.0, 1e-9);
  ASSERT_LE(plan.first_inside, plan.last_inside);
  ASSERT_LT(plan.last_inside, waypoints.size());
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
    const Point2 a = waypoints[i].position();
    const Point2 b = waypoints[i + 1].position();
    length += (b - a).norm();
    EXPECT_GT((b - a).norm(), 0.0) << "repeated waypoint " << i;
    EXPECT_NEAR(
        std::remainder(waypoints[i].yaw - std::atan2(b.y() - a.y(), b.x() - a.x()), 2 * M_PI), 0.0,
        1e-9);
    if (i >= plan.first_inside && i + 1 <= plan.last_inside) {
      // Inside the route area, or out of it toward the exact offset's boundary (the
      // repair's excursions), keeping the wall distance.
      EXPECT_TRUE(
          segmentInside(plan.route_area, a, b, kLegTolerance) ||
          keepsClearance(testing::sampledWallDistance(free_area, {a, b}), parameters.wall_distance))
          << "leg " << i << " from " << a.transpose() << " to " << b.transpose()
          << " leaves the route area (the offset free area's parts and their gaps) and comes "
             "nearer the walls than the wall distance";
    }
  }
  EXPECT_NEAR(plan.path_length_m, length, 1e-6 * std::max(1.0, length));
  EXPECT_GE(plan.time_cost_s, plan.path_length_m / parameters.v_max - 1e-9);
  // The exact offset the plan hands on is the one around its parts.
  const std::vector<PolygonWithHoles> exact =
      exactOffsetParts(free_area, parameters.wall_distance, plan.offset_parts);
  EXPECT_EQ(plan.exact_offset_parts.size(), exact.size());
  EXPECT_NEAR(area(plan.exact_offset_parts), area(exact), 1e-9 * std::max(1.0, area(exact)));
  const FrustumSensor sensor = sensorOf(parameters);
  const double covered = waypointPathReachableCoveragePercent(
      free_area, plan.offset_parts, sensor, waypoints, RasterResolution{0.0, 1e-3, 1'000'000});
  if (sensor.length() <= sensor.width()) {
    EXPECT_GE(covered, kReachableCoverageBarPercent);
  } else {
    // Lanes along walls see W/2 beside them, less than the reachable L/2: the plan must
    // say so, and what stays unseen is at most the documented band, (L - W)/2 wide along
    // the offset parts' boundaries (bounded above through the free area, which holds the
    // reachable area; kBandSlack for the raster's cells along it).
    EXPECT_TRUE(std::any_of(plan.warnings.begin(), plan.warnings.end(),
                            [](const std::string& warning) {
                              return warning.find("footprint is longer") != std::string::npos;
                            }))
        << "reachable coverage " << covered << " %";
    constexpr double kBandSlack = 1.1;
    double boundary = 0.0;
    for (const PolygonWithHoles& part : plan.offset_parts) boundary += boundaryLength(part);
    const double band = 0.5 * (sensor.length() - sensor.width()) * boundary;
    EXPECT_LE((100.0 - covered) / 100.0 * area(free_area), kBandSlack * band)
        << "reachable coverage " << covered << " %";
  }
}

}  // namespace kinematic_coverage::core
