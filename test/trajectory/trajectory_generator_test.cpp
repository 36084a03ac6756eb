#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

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

/// The waypoints' bounding box grown by `margin` m.
PolygonWithHoles boundingHull(const std::vector<Pose2>& waypoints, double margin = 5.0) {
  double x0 = waypoints.front().x, x1 = x0, y0 = waypoints.front().y, y1 = y0;
  for (const Pose2& p : waypoints) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  PolygonWithHoles area;
  area.hull = {{x0 - margin, y0 - margin},
               {x1 + margin, y0 - margin},
               {x1 + margin, y1 + margin},
               {x0 - margin, y1 + margin}};
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

TEST(TrajectoryGenerator, ClothoidTurnsKeepTheArcsGuaranteesOnRandomLawnmowers) {
  // turn_curve: clothoid under every strategy: a valid path ending at the last waypoint,
  // curvature at most 1 / r and continuous wherever a clothoid joins, curvature rates at
  // most curvature_rate_max, and no nearer an obstacle than the arcs.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> radius(0.5, 2.5);
  int clothoids = 0;
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<Pose2> waypoints = randomLawnmower(rng, 6);
    const PolygonWithHoles area = boundingHull(waypoints);
    for (const char* strategy : {"local", "global", "coverage_safe"}) {
      PlannerParameters arcs;
      arcs.turning_radius = radius(rng);
      arcs.smoothing_strategy = strategy;
      PlannerParameters continuous = arcs;
      continuous.turn_curve = "clothoid";
      const GeneratedTrajectory with_arcs =
          TrajectoryGenerator(trajectoryOptionsOf(arcs)).generate(waypoints, area);
      const GeneratedTrajectory with_clothoids =
          TrajectoryGenerator(trajectoryOptionsOf(continuous)).generate(waypoints, area);
      const std::vector<PathPrimitive>& path = with_clothoids.path;
      EXPECT_NO_THROW(validatePrimitivePath(path)) << strategy;
      EXPECT_LE(with_clothoids.max_curvature, 1.0 / arcs.turning_radius + 1e-9) << strategy;
      EXPECT_GE(with_clothoids.min_obstacle_clearance_m,
                with_arcs.min_obstacle_clearance_m - 2.0 * kClothoidDistanceTolerance)
          << strategy;
      EXPECT_NEAR((with_clothoids.poses.back().position() - waypoints.back().position()).norm(),
                  0.0, 1e-6)
          << strategy;
      for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i].kind() != PrimitiveKind::kClothoid) continue;
        ++clothoids;
        EXPECT_LE(std::abs(path[i].curvatureRate()), continuous.curvature_rate_max + 1e-12);
        ASSERT_GT(i, 0u);
        ASSERT_LT(i + 1, path.size());
        EXPECT_NEAR(path[i].curvatureAt(0.0), path[i - 1].curvatureAt(1.0), 1e-9) << i;
        EXPECT_NEAR(path[i].curvatureAt(1.0), path[i + 1].curvatureAt(0.0), 1e-9) << i;
      }
      EXPECT_EQ(with_clothoids.statistics.clothoid * 2,
                static_cast<int>(std::count_if(
                    path.begin(), path.end(),
                    [](const PathPrimitive& p) { return p.kind() == PrimitiveKind::kClothoid; })))
          << strategy;
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(clothoids, 100);
}

/// Relative slack of a traversal-time comparison: the global programme's times are exact
/// but where a leg piece is too short for the speed change between its neighbours.
constexpr double kTimeTolerance = 1e-3;

TEST(TrajectoryGenerator, SmoothingClearanceKeepsEveryTurnOffTheWalls) {
  // Lanes ending 1.5 m from the hull, turning radii up to 2.5 m: with smoothing_clearance
  // c < 1.5 m no primitive comes within c of the hull under any strategy or turn curve
  // (within kClearanceTolerance; the legs keep 1.5 m), corners that cannot keep it stay
  // sharp, and a clearance never smooths more of Algorithm 1's corners than none, nor
  // makes the global programme's optimum faster (coverage-safe smoothing, which drops
  // smoothings the whole path's coverage check refuses and chooses again, is no optimum).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> radius(0.5, 2.5);
  int blocked = 0;
  for (int trial = 0; trial < 15; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<Pose2> waypoints = randomLawnmower(rng, 5);
    const PolygonWithHoles area = boundingHull(waypoints, 1.5);
    const double turning_radius = radius(rng);
    for (const char* strategy : {"local", "global", "coverage_safe"}) {
      for (const char* curve : {"arc", "clothoid"}) {
        PlannerParameters parameters;
        parameters.turning_radius = turning_radius;
        parameters.smoothing_strategy = strategy;
        parameters.turn_curve = curve;
        parameters.smoothing_clearance = 0.0;
        const GeneratedTrajectory free =
            TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, area);
        for (const double clearance : {0.5, 1.0}) {
          parameters.smoothing_clearance = clearance;
          const GeneratedTrajectory kept =
              TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, area);
          EXPECT_NO_THROW(validatePrimitivePath(kept.path)) << strategy << " " << curve;
          EXPECT_GE(kept.min_obstacle_clearance_m, clearance - kClearanceTolerance)
              << strategy << " " << curve << " " << clearance;
          if (std::string(strategy) == "local") {
            EXPECT_LE(kept.statistics.turns_smoothed, free.statistics.turns_smoothed)
                << curve << " " << clearance;
          } else if (std::string(strategy) == "global") {
            // The jointly chosen smoothings: fewer candidates, never a faster optimum.
            EXPECT_GE(kept.traversal_time_s, free.traversal_time_s * (1.0 - kTimeTolerance))
                << strategy << " " << curve << " " << clearance;
          }
          if (kept.statistics.turns_smoothed < free.statistics.turns_smoothed) ++blocked;
        }
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(blocked, 20);
}

TEST(TrajectoryGenerator, KeepsTheWallDistanceByDefaultWithLegsOnTheOffsetBoundary) {
  // A lawnmower whose lane ends and joining legs lie exactly wall_distance (1 m) from the
  // hull, lanes 2.5 m apart: by default every turn keeps 1 m (within kClearanceTolerance)
  // and the legs on the offset boundary do not block the inner arcs; the thesis's
  // no-contact check (smoothing_clearance 0) lets outer turns of a wider radius swing into
  // the wall band.
  const std::vector<Pose2> waypoints = {{1.0, 1.0, 0.0}, {1.0, 9.0, 0.0}, {3.5, 9.0, 0.0},
                                        {3.5, 1.0, 0.0}, {6.0, 1.0, 0.0}, {6.0, 9.0, 0.0},
                                        {8.5, 9.0, 0.0}, {8.5, 1.0, 0.0}};
  PolygonWithHoles area;
  area.hull = {{0.0, 0.0}, {9.5, 0.0}, {9.5, 10.0}, {0.0, 10.0}};
  for (const char* strategy : {"local", "global", "coverage_safe"}) {
    for (const double radius : {1.0, 1.3}) {
      PlannerParameters parameters;
      parameters.smoothing_strategy = strategy;
      parameters.turning_radius = radius;
      const GeneratedTrajectory kept =
          TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, area);
      EXPECT_GE(kept.min_obstacle_clearance_m, 1.0 - kClearanceTolerance) << strategy << radius;
      if (radius == 1.0 && std::string(strategy) != "coverage_safe") {
        EXPECT_EQ(kept.statistics.turns_smoothed, 6) << strategy;
      }
      parameters.smoothing_clearance = 0.0;
      const GeneratedTrajectory thesis =
          TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(waypoints, area);
      if (radius == 1.3 && std::string(strategy) == "coverage_safe") {
        EXPECT_LT(thesis.min_obstacle_clearance_m, 1.0 - kClearanceTolerance) << strategy;
        // The closest approach is a point of the trajectory that near the hull.
        const PathPrimitive at = PathPrimitive::rotation(thesis.closest_approach, 0.0, 0.0);
        EXPECT_NEAR(primitivePathClearance({at}, area), thesis.min_obstacle_clearance_m, 0.01);
        double on_path = std::numeric_limits<double>::infinity();
        for (const PathPrimitive& primitive : thesis.path) {
          on_path = std::min(on_path, distancePointToPrimitive(thesis.closest_approach, primitive));
        }
        EXPECT_LT(on_path, 1e-9);
      }
      EXPECT_GE(thesis.statistics.turns_smoothed, kept.statistics.turns_smoothed) << strategy;
    }
  }
}

TEST(TrajectoryGenerator, LeavesTheWayInFromAStartInTheWallBandOutOfTheClearance) {
  // The start lies 0.3 m from the hull, the goal 0.2 m: their legs to and from the offset
  // free area are the one exception to keeping wall_distance, so min_obstacle_clearance_m
  // measures the rest (1 m); without a wall distance nothing is excepted.
  const std::vector<Pose2> waypoints = {
      {0.3, 5.0, 0.0}, {1.0, 5.0, 0.0}, {1.0, 9.0, 0.0}, {9.0, 9.0, 0.0}, {9.0, 9.8, 0.0}};
  PolygonWithHoles area;
  area.hull = {{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}};
  PlannerParameters parameters;
  for (const bool smoothing : {false, true}) {
    parameters.smoothing = smoothing;
    TrajectoryOptions options = trajectoryOptionsOf(parameters);
    const GeneratedTrajectory excepted = TrajectoryGenerator(options).generate(waypoints, area);
    EXPECT_NEAR(excepted.min_obstacle_clearance_m, 1.0, kClearanceTolerance) << smoothing;
    options.wall_distance = 0.0;
    const GeneratedTrajectory measured = TrajectoryGenerator(options).generate(waypoints, area);
    EXPECT_NEAR(measured.min_obstacle_clearance_m, 0.2, 1e-9) << smoothing;
  }
  // The way out to the goal continues a lane: smoothing merges the two collinear legs into
  // one segment, of which only the part beyond the offset free area is excepted.
  const std::vector<Pose2> collinear = {{0.3, 5.0, 0.0}, {1.0, 5.0, 0.0}, {1.0, 2.0, 0.0},
                                        {5.0, 2.0, 0.0}, {9.0, 2.0, 0.0}, {9.8, 2.0, 0.0}};
  for (const bool smoothing : {false, true}) {
    parameters.smoothing = smoothing;
    const GeneratedTrajectory excepted =
        TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(collinear, area);
    EXPECT_NEAR(excepted.min_obstacle_clearance_m, 1.0, kClearanceTolerance) << smoothing;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
