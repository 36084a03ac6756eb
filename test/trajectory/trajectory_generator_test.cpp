#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/parameters/stage_options.h"

namespace kinematic_coverage::core {
namespace {

/// A lawnmower of `lanes` lanes 2 m apart with random lane lengths and random jogs between
/// lanes, in a hull with 5 m of margin: the kind of path the planner hands over.
std::vector<Pose2> randomLawnmower(std::mt19937& rng, int lanes) {
  std::uniform_real_distribution<double> length(4.0, 40.0);
  std::uniform_real_distribution<double> jog(-3.0, 3.0);
  std::vector<Pose2> waypoints;
  double y = 0.0;
  for (int i = 0; i < lanes; ++i) {
    const double x = 2.0 * i;
    const double end = y + (i % 2 == 0 ? 1.0 : -1.0) * length(rng);
    waypoints.push_back({x, y, 0.0});
    waypoints.push_back({x, end, 0.0});
    y = end + jog(rng);
  }
  return waypoints;
}

PolygonWithHoles boundingHull(const std::vector<Pose2>& waypoints) {
  double x0 = waypoints.front().x, x1 = x0, y0 = waypoints.front().y, y1 = y0;
  for (const Pose2& p : waypoints) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  PolygonWithHoles area;
  area.hull = {{x0 - 5, y0 - 5}, {x1 + 5, y0 - 5}, {x1 + 5, y1 + 5}, {x0 - 5, y1 + 5}};
  return area;
}

TEST(TrajectoryGenerator, RejectsAMinTurningRadiusAboveTheTurningRadius) {
  PlannerParameters parameters;
  parameters.min_turning_radius = 2.0 * parameters.turning_radius;
  const std::vector<Pose2> waypoints{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}};
  EXPECT_THROW(TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, {}),
               InvalidInputError);
}

/// One waypoint (or several at one place) is a robot that stays: one pose, with the first
/// waypoint's heading, under every strategy; no waypoint is invalid.
TEST(TrajectoryGenerator, OneWaypointGivesOnePoseAndNoneIsInvalid) {
  const PolygonWithHoles area{{{-5, -5}, {5, -5}, {5, 5}, {-5, 5}}, {}};
  for (const char* strategy : {"coverage_safe", "global", "local", "none"}) {
    SCOPED_TRACE(strategy);
    PlannerParameters parameters;
    parameters.smoothing = std::string(strategy) != "none";
    if (parameters.smoothing) parameters.smoothing_strategy = strategy;
    for (const std::vector<Pose2>& waypoints :
         {std::vector<Pose2>{{1, 2, 0.5}}, std::vector<Pose2>{{1, 2, 0.5}, {1, 2, -1.0}}}) {
      const GeneratedTrajectory trajectory =
          TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, area);
      ASSERT_EQ(trajectory.poses.size(), 1u);
      EXPECT_EQ(trajectory.poses[0].x, 1.0);
      EXPECT_EQ(trajectory.poses[0].y, 2.0);
      EXPECT_NEAR(trajectory.poses[0].yaw, 0.5, 1e-12);
      EXPECT_EQ(trajectory.poses[0].t, 0.0);
      EXPECT_EQ(trajectory.traversal_time_s, 0.0);
    }
    EXPECT_THROW(TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate({}, area),
                 InvalidInputError);
    EXPECT_THROW(
        TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate({{std::nan(""), 0, 0}}, area),
        InvalidInputError);
  }
}

TEST(TrajectoryGenerator, GlobalIsNeverSlowerThanLocalOnRandomLawnmowers) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> radius(0.5, 2.5);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<Pose2> waypoints = randomLawnmower(rng, 8);
    const PolygonWithHoles area = boundingHull(waypoints);
    PlannerParameters local;
    local.turning_radius = radius(rng);
    local.smoothing_strategy = "local";
    PlannerParameters global = local;
    global.smoothing_strategy = "global";
    PlannerParameters variable = global;
    variable.min_turning_radius = 0.3 * global.turning_radius;
    const GeneratedTrajectory by_local =
        TrajectoryGenerator(trajectoryOptionsOf(local)).generate(waypoints, area);
    const GeneratedTrajectory by_global =
        TrajectoryGenerator(trajectoryOptionsOf(global)).generate(waypoints, area);
    const GeneratedTrajectory by_variable =
        TrajectoryGenerator(trajectoryOptionsOf(variable)).generate(waypoints, area);
    EXPECT_LE(by_global.traversal_time_s, by_local.traversal_time_s + 1e-9);
    EXPECT_LE(by_global.max_curvature, 1.0 / global.turning_radius + 1e-9);
    EXPECT_LE(by_variable.max_curvature, 1.0 / variable.min_turning_radius + 1e-9);
    for (const GeneratedTrajectory* t : {&by_local, &by_global, &by_variable}) {
      EXPECT_GT(t->min_obstacle_clearance_m, 0.0);
      EXPECT_NEAR((t->poses.back().position() - waypoints.back().position()).norm(), 0.0, 1e-9);
    }
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
