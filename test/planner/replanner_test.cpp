#include "coverage_system/planner/replanner.h"

#include <gtest/gtest.h>

#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/replanning/drift_scenario.h"

namespace kinematic_coverage::core {
namespace {

/// The drift scenario: the new trajectory starts at the last visited pose, avoids
/// the moved obstacles, and the visited plus new footprints see at least 99 % of the
/// updated reachable area.
TEST(Replanner, LakeDriftScenarioCoversTheUpdatedReachableArea) {
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {2.0, 1.0});
  const PlannerParameters& parameters = scenario.mission.parameters;
  const ReplannedMission replanned =
      Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
  ASSERT_GE(replanned.plan.waypoints.size(), 2u);
  const Point2 last = scenario.visited.back().position();
  EXPECT_LT((replanned.plan.waypoints.front().position() - last).norm(), 1e-9);
  EXPECT_LT((replanned.plan.waypoints.back().position() - scenario.mission.goal).norm(), 1e-9);
  EXPECT_FALSE(replanned.remaining.parts.empty());
  for (const PolygonWithHoles& part : replanned.remaining.parts) {
    EXPECT_NO_THROW(PolygonValidator().validate(part));
  }

  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(trajectoryOptionsOf(parameters))
          .generate(replanned.plan.waypoints, replanned.free_area);
  ASSERT_FALSE(trajectory.poses.empty());
  EXPECT_LT((trajectory.poses.front().position() - last).norm(), 1e-9);
  EXPECT_GT(trajectory.min_obstacle_clearance_m, 0.0);
  for (const TrajectoryPose& pose : trajectory.poses) {
    for (const Ring& hole : scenario.updated.holes) {
      EXPECT_FALSE(insideRing(pose.position(), hole) &&
                   distanceToRing(pose.position(), hole) > 1e-9)
          << pose.x << ", " << pose.y;
    }
  }
  EXPECT_GE(testing::combinedReachableCoverage(replanned.free_area, parameters, scenario.visited,
                                               trajectory.poses),
            99.0);
}

/// A replanned drift scenario: whether its plan has the stage `name`, and the reachable
/// coverage of the visited and the new (unsmoothed) footprints together.
struct ReplannedCoverage {
  bool has_stage = false;
  double combined = 0.0;
};

ReplannedCoverage replannedCoverage(const testing::DriftScenario& scenario,
                                    PlannerParameters parameters, const std::string& name) {
  const ReplannedMission replanned =
      Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
  ReplannedCoverage result;
  for (const PlanningStage& stage : replanned.plan.stages) result.has_stage |= stage.name == name;
  parameters.smoothing = false;
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(trajectoryOptionsOf(parameters))
          .generate(replanned.plan.waypoints, replanned.free_area);
  result.combined = testing::combinedReachableCoverage(replanned.free_area, parameters,
                                                       scenario.visited, trajectory.poses);
  return result;
}

/// With coverage_repair, the replanned path is repaired too (stage `repair`), against the
/// remaining area: the visited and new footprints together see at least what they see
/// without it.
TEST(Replanner, CoverageRepairRepairsTheReplannedPath) {
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {2.0, 1.0});
  double combined[2] = {0.0, 0.0};
  for (const bool repair : {false, true}) {
    PlannerParameters parameters = scenario.mission.parameters;
    parameters.coverage_repair = repair;
    const ReplannedCoverage replanned = replannedCoverage(scenario, parameters, "repair");
    EXPECT_EQ(replanned.has_stage, repair);
    combined[repair ? 1 : 0] = replanned.combined;
  }
  EXPECT_GE(combined[1], combined[0] - 1e-9);
  EXPECT_GE(combined[1], 99.9);
}

/// Replanning decomposes the remaining region simplified too (stage `simplify`): the lanes go
/// on to the region's exact boundary, and the visited and new footprints together see the
/// reachable area as with the exact region (0.1 point allowed).
TEST(Replanner, ASimplifiedRegionIsReplannedAndSeen) {
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {2.0, 1.0});
  double combined[2] = {0.0, 0.0};
  for (const double simplification : {0.0, 0.1}) {
    PlannerParameters parameters = scenario.mission.parameters;
    parameters.boundary_simplification = simplification;
    const ReplannedCoverage replanned = replannedCoverage(scenario, parameters, "simplify");
    EXPECT_EQ(replanned.has_stage, simplification > 0.0);
    combined[replanned.has_stage ? 1 : 0] = replanned.combined;
  }
  EXPECT_GE(combined[1], combined[0] - 0.1);
}

/// Every method gives valid parts and a plan; the convex hull discards unvisited area, so
/// it keeps no more than the footprint method (thesis Fig. 3.9 and 3.11).
TEST(Replanner, EveryMethodGivesValidPartsAndAPlan) {
  // The lake's footprint is 12.9 m wide: after a quarter of the trajectory much is left.
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.25, {-2.0, 0.5});
  double kept[3] = {0, 0, 0};
  int k = 0;
  for (const char* method : {"convex_hull", "concave_hull", "footprint"}) {
    SCOPED_TRACE(method);
    PlannerParameters parameters = scenario.mission.parameters;
    parameters.replanning_method = method;
    const ReplannedMission replanned =
        Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
    for (const PolygonWithHoles& part : replanned.remaining.parts) {
      EXPECT_NO_THROW(PolygonValidator().validate(part));
    }
    EXPECT_GE(replanned.plan.waypoints.size(), 2u);
    EXPECT_LE(replanned.remaining.seen_area_m2, replanned.remaining.free_area_m2 + 1e-9);
    kept[k++] = replanned.remaining.kept_area_m2;
  }
  EXPECT_LE(kept[0], kept[2] + 1e-6);
  EXPECT_GT(kept[2], 0.0);
}

TEST(Replanner, StartInsideAMovedHole) {
  testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {0.0, 0.0});
  const PlannerParameters& parameters = scenario.mission.parameters;
  // Just inside the rectangle [7, 12] x [9, 15]: starts from its edge.
  scenario.visited.push_back({7.4, 12.0, 0.0});
  const ReplannedMission replanned =
      Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
  EXPECT_NEAR(replanned.start.x(), 7.0, 1e-5);
  EXPECT_NEAR(replanned.start.y(), 12.0, 1e-9);
  // Deeper than wall_distance: invalid.
  scenario.visited.push_back({9.5, 12.0, 0.0});
  EXPECT_THROW(
      Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal),
      InvalidInputError);
}

TEST(Replanner, InvalidInput) {
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.2, {1.0, 1.0});
  const PlannerParameters& parameters = scenario.mission.parameters;
  const Replanner replanner(parameters);
  EXPECT_THROW(replanner.replan(scenario.updated, {}, scenario.mission.goal), InvalidInputError);
  std::vector<Pose2> bad = scenario.visited;
  bad.push_back({std::nan(""), 1.0, 0.0});
  EXPECT_THROW(replanner.replan(scenario.updated, bad, scenario.mission.goal), InvalidInputError);
  PolygonWithHoles crossing = scenario.updated;
  crossing.hull = {{0, 0}, {30, 30}, {30, 0}, {0, 30}};
  EXPECT_THROW(replanner.replan(crossing, scenario.visited, scenario.mission.goal),
               InvalidInputError);
  EXPECT_THROW(replanner.replan(scenario.updated, scenario.visited, {10, 12}), InvalidInputError);
}

/// The lake with `followed` of its trajectory driven and no obstacle moved, replanned to
/// `goal` with parts under `min_area` (m^2) dropped.
ReplannedMission replannedLake(double followed, double min_area, const Point2& goal) {
  const testing::DriftScenario scenario = testing::lakeDriftScenario(followed, {0.0, 0.0});
  PlannerParameters parameters = scenario.mission.parameters;
  parameters.replanning_min_area = min_area;
  return Replanner(parameters).replan(scenario.updated, scenario.visited, goal);
}

/// Everything seen already: no parts, and the plan goes from the last pose to the goal.
TEST(Replanner, NothingLeftGoesToTheGoal) {
  const ReplannedMission replanned = replannedLake(1.0, 50.0, {20, 2});
  EXPECT_TRUE(replanned.remaining.parts.empty());
  ASSERT_GE(replanned.plan.waypoints.size(), 2u);
  EXPECT_LT((replanned.plan.waypoints.back().position() - Point2(20, 2)).norm(), 1e-9);
  EXPECT_TRUE(replanned.plan.cells.empty());
}

TEST(Replanner, PartsTooSmallToPlanAreNamedInAWarning) {
  // Half the lake followed; a minimum area above the lake's leaves every part unplanned.
  const ReplannedMission replanned = replannedLake(0.5, 1000.0, {29, 29});
  EXPECT_TRUE(replanned.remaining.parts.empty());
  // Every part left unplanned is named in one warning: its area and where it lies.
  ASSERT_FALSE(replanned.remaining.dropped.empty());
  std::string warning;
  for (const std::string& w : replanned.warnings) {
    if (w.find("not replanned") != std::string::npos) warning = w;
  }
  ASSERT_FALSE(warning.empty());
  EXPECT_EQ(warning.rfind(std::to_string(replanned.remaining.dropped.size()) + " parts", 0), 0u)
      << warning;
  EXPECT_NE(warning.find("smaller than replanning_min_area (1000 m^2)"), std::string::npos)
      << warning;
  std::size_t arounds = 0;
  for (std::size_t at = warning.find(" around ("); at != std::string::npos;
       at = warning.find(" around (", at + 1)) {
    ++arounds;
  }
  EXPECT_EQ(arounds, replanned.remaining.dropped.size());
}
}  // namespace
}  // namespace kinematic_coverage::core

namespace kinematic_coverage::core {
namespace {

TEST(Replanner, RepeatedReplansOfOneScenarioAreIdentical) {
  // The remaining area's simplification must not depend on where the heap puts CGAL's
  // constraints: each method, replanned again and again in one process, gives one answer.
  const testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {2.0, 1.0});
  for (const char* method : {"footprint", "concave_hull"}) {
    SCOPED_TRACE(method);
    PlannerParameters parameters = scenario.mission.parameters;
    parameters.replanning_method = method;
    const ReplannedMission first =
        Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
    for (int run = 0; run < 8; ++run) {
      const ReplannedMission again =
          Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
      ASSERT_EQ(again.remaining.parts.size(), first.remaining.parts.size()) << "run " << run;
      for (std::size_t i = 0; i < first.remaining.parts.size(); ++i) {
        ASSERT_EQ(again.remaining.parts[i].hull, first.remaining.parts[i].hull) << "run " << run;
        ASSERT_EQ(again.remaining.parts[i].holes, first.remaining.parts[i].holes);
      }
      ASSERT_EQ(again.plan.waypoints.size(), first.plan.waypoints.size()) << "run " << run;
      for (std::size_t i = 0; i < first.plan.waypoints.size(); ++i) {
        ASSERT_EQ(again.plan.waypoints[i].x, first.plan.waypoints[i].x) << "run " << run;
        ASSERT_EQ(again.plan.waypoints[i].y, first.plan.waypoints[i].y) << "run " << run;
      }
    }
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
