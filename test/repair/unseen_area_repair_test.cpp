#include "polygon_coverage_ros_bridge/repair/unseen_area_repair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/support/hard_map_generator.h"
#include "test/support/sampled_wall_distance.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {
namespace {

/// Legs may leave the offset free area by this much (rounding).
constexpr double kLegTolerance = 1e-6;

/// Unseen reachable area (m^2) of a waypoint path, the rim measured exactly.
double unseenArea(const PolygonWithHoles& free_area, const std::vector<PolygonWithHoles>& parts,
                  const FrustumSensor& sensor, const std::vector<Point2>& waypoints) {
  const CoverageEvaluator evaluator(free_area, parts, sensor, reportingResolution(),
                                    kReportingGridAngle);
  return evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(waypoints)))
      .unseen_reachable_area_m2;
}

/// True when `part` appears in `whole` in order (the repair keeps every waypoint).
bool isSubsequence(const std::vector<Point2>& part, const std::vector<Point2>& whole) {
  std::size_t k = 0;
  for (const Point2& p : whole) {
    if (k < part.size() && p == part[k]) ++k;
  }
  return k == part.size();
}

/// A 20 m x 10 m free area kept 1 m from its walls, a sensor 2 m wide and 1 m long.
struct Room {
  PolygonWithHoles free_area{{{0, 0}, {20, 0}, {20, 10}, {0, 10}}, {}};
  PolygonWithHoles offset{{{1, 1}, {19, 1}, {19, 9}, {1, 9}}, {}};
  FrustumSensor sensor{2.0, 1.0, 0.0};
  PlannerParameters parameters;
  SegmentCost cost{segmentCostOf(parameters)};
  VisibilityGraph graph{offset, cost};

  RepairedPath repair(const std::vector<Point2>& waypoints) const {
    return UnseenAreaRepair(free_area, 1.0, {offset}, sensor, graph, cost)
        .repair(waypoints, 0, waypoints.size() - 1);
  }
};

/// Lanes along x from 1 to 19 at the given heights, joined at alternating ends.
std::vector<Point2> lanesAt(const std::vector<double>& heights) {
  std::vector<Point2> waypoints;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const bool forward = k % 2 == 0;
    waypoints.push_back({forward ? 1.0 : 19.0, heights[k]});
    waypoints.push_back({forward ? 19.0 : 1.0, heights[k]});
  }
  return waypoints;
}

void expectInside(const PolygonWithHoles& area, const std::vector<Point2>& waypoints) {
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
    EXPECT_TRUE(segmentInside(area, waypoints[i], waypoints[i + 1], kLegTolerance))
        << "leg " << i << " from " << waypoints[i].transpose() << " to "
        << waypoints[i + 1].transpose();
  }
}

// Lanes 2 m apart from y = 1.5 see y 0.5 to 8.5; the reachable area reaches y = 9.5 (L/2
// beyond the offset area), so a band 1 m high along the top stays unseen. The repair drives
// along the top of the offset area and sees it, keeping every waypoint of the path.
TEST(UnseenAreaRepair, ABandAlongTheBoundaryIsSeenFromTheBoundary) {
  const Room room;
  const std::vector<Point2> lanes = lanesAt({1.5, 3.5, 5.5, 7.5});
  const RepairedPath repaired = room.repair(lanes);
  EXPECT_NEAR(repaired.unseen_before_m2, 19.0, 0.2);
  EXPECT_LT(repaired.unseen_after_m2, 0.01);
  EXPECT_GE(repaired.patches, 1u);
  EXPECT_LT(unseenArea(room.free_area, {room.offset}, room.sensor, repaired.waypoints), 0.01);
  EXPECT_TRUE(isSubsequence(lanes, repaired.waypoints));
  EXPECT_EQ(repaired.waypoints.front(), lanes.front());
  EXPECT_EQ(repaired.waypoints.back(), lanes.back());
  EXPECT_EQ(repaired.last_inside, repaired.waypoints.size() - 1);
  expectInside(room.offset, repaired.waypoints);
  // The patch runs along the top of the offset area.
  double along_top = 0.0;
  for (std::size_t i = 0; i + 1 < repaired.waypoints.size(); ++i) {
    const Point2& a = repaired.waypoints[i];
    const Point2& b = repaired.waypoints[i + 1];
    if (std::abs(a.y() - 9.0) < 1e-9 && std::abs(b.y() - 9.0) < 1e-9) along_top += (b - a).norm();
  }
  EXPECT_GT(along_top, 17.0);
}

// A transition whose view the lanes already have is replaced by the detour through the
// patch: from the last lane's end up to the top of the offset area, along it, and down to
// where the transition went, about 8 m more than the transition instead of a 38 m spur.
TEST(UnseenAreaRepair, ATransitionNothingNeedsIsReplacedByTheDetour) {
  const Room room;
  std::vector<Point2> path = lanesAt({1.5, 3.5, 5.5, 7.5});
  path.push_back({19, 1.5});
  const RepairedPath repaired = room.repair(path);
  EXPECT_LT(repaired.unseen_after_m2, 0.01);
  for (std::size_t i = 0; i + 1 < repaired.waypoints.size(); ++i) {
    EXPECT_FALSE(repaired.waypoints[i] == Point2(1, 7.5) &&
                 repaired.waypoints[i + 1] == Point2(19, 1.5));
  }
  EXPECT_LT(pathLength(repaired.waypoints) - pathLength(path), 10.0);
  expectInside(room.offset, repaired.waypoints);
}

// A gap between lanes deep inside the offset area (y 4.5 to 6.5, from x = 2 where the
// join between the lanes sees it to x = 19.5: about 35 m^2) is seen from a patch through it.
TEST(UnseenAreaRepair, AGapBetweenLanesIsSeenFromAPatchThroughIt) {
  const Room room;
  const std::vector<Point2> lanes = lanesAt({1.5, 3.5, 7.5, 8.5});
  const RepairedPath repaired = room.repair(lanes);
  EXPECT_NEAR(repaired.unseen_before_m2, 35.0, 0.5);
  EXPECT_LT(repaired.unseen_after_m2, 0.01);
  EXPECT_TRUE(isSubsequence(lanes, repaired.waypoints));
  expectInside(room.offset, repaired.waypoints);
}

// A path that sees all of the reachable area is returned as it is.
TEST(UnseenAreaRepair, APathThatSeesEverythingIsLeftAsItIs) {
  const Room room;
  const std::vector<Point2> lanes = lanesAt({1.5, 3.5, 5.5, 7.5, 8.5});
  const RepairedPath repaired = room.repair(lanes);
  EXPECT_EQ(repaired.waypoints, lanes);
  EXPECT_EQ(repaired.patches, 0u);
  EXPECT_EQ(repaired.unseen_before_m2, 0.0);
  EXPECT_EQ(repaired.unseen_after_m2, 0.0);
  // The 18 m x 8 m offset area grown by L/2 = 0.5 m, with rounded corners.
  EXPECT_NEAR(repaired.reachable_m2, 18.0 * 8.0 + 26.0 + 0.25 * M_PI, 0.05);
}

// Legs outside [first_inside, last_inside] (joining a start and goal outside the offset
// area) get no patch, and the waypoints beyond them stay where they are.
TEST(UnseenAreaRepair, LegsToAStartAndGoalOutsideTheAreaGetNoPatch) {
  const Room room;
  std::vector<Point2> path = lanesAt({1.5, 3.5, 5.5, 7.5});
  path.insert(path.begin(), Point2(0.5, 1.5));
  path.push_back({0.5, 7.5});
  const RepairedPath repaired =
      UnseenAreaRepair(room.free_area, 1.0, {room.offset}, room.sensor, room.graph, room.cost)
          .repair(path, 1, path.size() - 2);
  EXPECT_LT(repaired.unseen_after_m2, 0.01);
  EXPECT_EQ(repaired.waypoints.front(), path.front());
  EXPECT_EQ(repaired.waypoints[1], path[1]);
  EXPECT_EQ(repaired.waypoints.back(), path.back());
  EXPECT_EQ(repaired.last_inside, repaired.waypoints.size() - 2);
  const std::vector<Point2> inside(repaired.waypoints.begin() + 1, repaired.waypoints.end() - 1);
  expectInside(room.offset, inside);
}

// With a coverage region (a replanned mission's remaining area), only the reachable area
// inside it is patched: of the 1 m band that the lanes leave along the top, the left half
// (x < 10); a region where everything is seen gets no patch.
TEST(UnseenAreaRepair, OnlyTheCoverageRegionIsPatched) {
  const Room room;
  const std::vector<Point2> lanes = lanesAt({1.5, 3.5, 5.5, 7.5});
  const std::vector<PolygonWithHoles> left{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}}};
  const RepairedPath repaired = UnseenAreaRepair(room.free_area, 1.0, {room.offset}, room.sensor,
                                                 room.graph, room.cost, &left)
                                    .repair(lanes, 0, lanes.size() - 1);
  EXPECT_NEAR(repaired.unseen_before_m2, 9.5, 0.2);
  EXPECT_LT(repaired.unseen_after_m2, 0.01);
  EXPECT_GE(repaired.patches, 1u);
  EXPECT_TRUE(isSubsequence(lanes, repaired.waypoints));
  expectInside(room.offset, repaired.waypoints);
  // Less driving than seeing the whole band (a walk along all of the top).
  EXPECT_LT(pathLength(repaired.waypoints), pathLength(room.repair(lanes).waypoints) - 5.0);

  const std::vector<PolygonWithHoles> bottom{{{{0, 0}, {20, 0}, {20, 5}, {0, 5}}, {}}};
  const RepairedPath untouched = UnseenAreaRepair(room.free_area, 1.0, {room.offset}, room.sensor,
                                                  room.graph, room.cost, &bottom)
                                     .repair(lanes, 0, lanes.size() - 1);
  EXPECT_EQ(untouched.waypoints, lanes);
  EXPECT_EQ(untouched.patches, 0u);
  EXPECT_EQ(untouched.unseen_before_m2, 0.0);
}

/// One lane repaired alone in `room` by the walls' mitred offset (its first part; the
/// mitres unlimited, as the thesis's), with a sensor 1 m wide and 0.5 m long, only the
/// reachable area inside `region` counting.
RepairedPath repairedLane(const PolygonWithHoles& room, double wall_distance,
                          const std::vector<PolygonWithHoles>& region,
                          const std::vector<Point2>& lane) {
  const std::vector<PolygonWithHoles> parts =
      computeOffsetFreeArea(room, wall_distance, kMaxMiterLimit).parts;
  const FrustumSensor sensor{1.0, 0.5, 0.0};
  const SegmentCost cost{segmentCostOf(PlannerParameters{})};
  const VisibilityGraph graph{parts.front(), cost};
  return UnseenAreaRepair(room, wall_distance, parts, sensor, graph, cost, &region)
      .repair(lane, 0, lane.size() - 1);
}

// A corner of a triangular obstacle bulges into the free area by 120 degrees: the mitred
// offset by the wall distance (2 m) stops 2 m short of the exact offset's round corner, and
// with a 1 m x 0.5 m footprint the reachable area around that corner is out of sight of the
// mitred boundary. The repair drives out of the mitre to the round corner and back, keeping
// the wall distance, and sees it.
TEST(UnseenAreaRepair, ARoundCornerOfTheExactOffsetIsSeenFromAnExcursion) {
  const double height = 3.0 * std::sqrt(3.0);
  const PolygonWithHoles room{{{0, 0}, {40, 0}, {40, 30}, {0, 30}},
                              {{{17, 13}, {20, 13 + height}, {23, 13}}}};
  const double wall_distance = 2.0;
  const std::vector<PolygonWithHoles> parts =
      computeOffsetFreeArea(room, wall_distance, kMaxMiterLimit).parts;
  // Where the obstacle's lower left corner bulges; a lane below it sees up to y = 11.
  const std::vector<PolygonWithHoles> near_corner{{{{13, 10}, {18, 10}, {18, 14}, {13, 14}}, {}}};
  const RepairedPath repaired =
      repairedLane(room, wall_distance, near_corner, {{3, 10.5}, {37, 10.5}});
  EXPECT_GT(repaired.unseen_before_m2, 5.0);
  EXPECT_LT(repaired.unseen_after_m2, 0.01 * repaired.unseen_before_m2);
  std::size_t beyond = 0;
  for (const Point2& p : repaired.waypoints) beyond += contains(parts.front(), p, 1e-6) ? 0 : 1;
  EXPECT_GE(beyond, 1u);
  EXPECT_TRUE(
      keepsClearance(testing::sampledWallDistance(room, repaired.waypoints), wall_distance));
}

// A slot 1.6 m wide opens from the top wall at y = 10 (wall distance 1 m): the exact offset
// bulges up to y = 9.4 at its mouth, out of sight of a lane along the mitred boundary at
// y = 9. The repair bends the lane out through the bulge's tip instead of driving out and
// back: no waypoint is turned back to, and every leg keeps the wall distance.
TEST(UnseenAreaRepair, ASlotsMouthIsSeenByBendingTheLaneOutThroughIt) {
  const PolygonWithHoles room{
      {{0, 0}, {20, 0}, {20, 10}, {10.8, 10}, {10.8, 15}, {9.2, 15}, {9.2, 10}, {0, 10}}, {}};
  const double wall_distance = 1.0;
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(room, wall_distance).parts;
  // The lane sees y = 8.5 to 9.5; only the mouth above it counts.
  const std::vector<PolygonWithHoles> near_mouth{{{{8, 8.6}, {12, 8.6}, {12, 10}, {8, 10}}, {}}};
  const std::vector<Point2> lane = {{1, 9}, {19, 9}};
  const RepairedPath repaired = repairedLane(room, wall_distance, near_mouth, lane);
  EXPECT_GT(repaired.unseen_before_m2, 0.01);
  EXPECT_LT(repaired.unseen_after_m2, 0.1 * repaired.unseen_before_m2);
  const std::vector<Point2>& path = repaired.waypoints;
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path.front(), lane.front());
  EXPECT_EQ(path.back(), lane.back());
  std::size_t beyond = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (contains(parts.front(), path[k], 1e-6)) continue;
    ++beyond;
    ASSERT_GT(k, 0u);
    ASSERT_LT(k + 1, path.size());
    EXPECT_LT(path[k - 1].x(), path[k].x());
    EXPECT_GT(path[k + 1].x(), path[k].x());
  }
  EXPECT_GE(beyond, 1u);
  for (std::size_t k = 0; k + 1 < path.size(); ++k) EXPECT_LT(path[k].x(), path[k + 1].x());
  EXPECT_TRUE(keepsClearance(testing::sampledWallDistance(room, path), wall_distance));
}

/// A mission planned as coverage_tool plans it, without and with coverage_repair, and the
/// two waypoint paths.
struct PlannedBothWays {
  PlannedMission without;
  PlannedMission with;
  std::vector<Point2> before;
  std::vector<Point2> after;
  FrustumSensor sensor{1.0, 0.0, 0.0};
};

PlannedBothWays planBothWays(Mission mission) {
  PlannedBothWays result;
  mission.parameters.coverage_repair = false;
  result.without = planMission(mission);
  mission.parameters.coverage_repair = true;
  result.with = planMission(mission);
  for (const Pose2& pose : result.without.plan.waypoints) result.before.push_back(pose.position());
  for (const Pose2& pose : result.with.plan.waypoints) result.after.push_back(pose.position());
  result.sensor = sensorOf(mission.parameters);
  return result;
}

// Rooms seed 4: the jog removal shifts the end of a room's top lane, which sees exactly to
// the reachable area's rim along the wall, 0.2 m inward, leaving a band 14 m long (1.9 m^2).
// Putting the jog back sees it for 0.3 % more time; a patch along the wall took 23 % more.
TEST(UnseenAreaRepair, AJogThatShiftedALaneOffTheWallIsPutBack) {
  const testing::HardMap map = testing::HardMapGenerator(testing::MapFamily::kRooms).generate(4);
  Mission mission = map.mission;
  mission.parameters.smoothing = false;
  const PlannedBothWays plans = planBothWays(mission);
  const PlannedMission& planned = plans.without;
  const PlannedMission& repaired = plans.with;
  const FrustumSensor& sensor = plans.sensor;
  const std::vector<Point2>& before = plans.before;
  const std::vector<Point2>& after = plans.after;
  const double wall_distance = mission.parameters.wall_distance;
  EXPECT_GT(
      unseenArea(planned.free_area,
                 exactOffsetParts(planned.free_area, wall_distance, planned.plan.offset_parts),
                 sensor, before),
      1.5);
  EXPECT_LT(
      unseenArea(repaired.free_area,
                 exactOffsetParts(repaired.free_area, wall_distance, repaired.plan.offset_parts),
                 sensor, after),
      0.01);
  EXPECT_LE(repaired.plan.time_cost_s, 1.01 * planned.plan.time_cost_s);
  EXPECT_EQ(after.size(), before.size() + 1);
}

// Shoreline seed 34 with its boundary simplified (boundary_simplification 0.1): the cells
// end short of 24 bays, 3 m^2 of reachable area. Spurs to them keep every leg, but the
// raster samples the legs they split a little differently and two cells (0.005 m^2) of
// the path's view flip: that must not reject the patches that see the 3 m^2.
TEST(UnseenAreaRepair, SpursAreTakenThoughTheLegsTheySplitLoseARasterSliver) {
  const testing::HardMap map =
      testing::HardMapGenerator(testing::MapFamily::kShoreline).generate(34);
  Mission mission = map.mission;
  mission.parameters.smoothing = false;
  mission.parameters.boundary_simplification = 0.1;
  const PlannedBothWays plans = planBothWays(mission);
  const PlannedMission& repaired = plans.with;
  const CoverageEvaluator evaluator(
      repaired.free_area,
      exactOffsetParts(repaired.free_area, mission.parameters.wall_distance,
                       repaired.plan.offset_parts),
      plans.sensor, reportingResolution(), kReportingGridAngle);
  const CoverageReport before =
      evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(plans.before)));
  const CoverageReport after =
      evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(plans.after)));
  EXPECT_GT(before.unseen_reachable_area_m2, 2.0);
  EXPECT_GE(after.reachable_coverage_percent, 99.9);
}

// Shorelines 36 and 44: reachable area in the funnel of a gap narrower than two wall
// distances (0.69 m between an obstacle and a shore spike at wall_distance 0.40; a gap of
// 1.54 m clearance to a part left out), which the exact offset reaches and the mitred one,
// stopped by the spikes, does not. One straight excursion toward it stops short (36: it
// cannot start); a walk along the funnel sees it, every leg out of the route area keeping
// the wall distance.
TEST(UnseenAreaRepair, AFunnelTowardANarrowGapIsSeenFromAWalkAlongIt) {
  for (const std::uint64_t seed : {36, 44}) {
    const testing::HardMap map =
        testing::HardMapGenerator(testing::MapFamily::kShoreline).generate(seed);
    Mission mission = map.mission;
    mission.parameters.smoothing = false;
    const PlannedBothWays plans = planBothWays(mission);
    const PlannedMission& repaired = plans.with;
    const double wall_distance = mission.parameters.wall_distance;
    const CoverageEvaluator evaluator(
        repaired.free_area,
        exactOffsetParts(repaired.free_area, wall_distance, repaired.plan.offset_parts),
        plans.sensor, reportingResolution(), kReportingGridAngle);
    const CoverageReport after =
        evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(plans.after)));
    EXPECT_GE(after.reachable_coverage_percent, 99.9) << "seed " << seed;
    const std::vector<Point2>& path = plans.after;
    for (std::size_t i = repaired.plan.first_inside; i < repaired.plan.last_inside; ++i) {
      EXPECT_TRUE(
          segmentInside(repaired.plan.route_area, path[i], path[i + 1], 1e-6) ||
          keepsClearance(testing::sampledWallDistance(repaired.free_area, {path[i], path[i + 1]}),
                         wall_distance))
          << "seed " << seed << " leg " << i;
    }
  }
}

// The planner with coverage_repair on the first maps of every hard-map family
// (test/support/hard_map_generator.h; of the shorelines the two that plan in about a
// second): every plan stays valid, sees at least what the unrepaired plan sees and at
// least 99.9 % of the reachable area of its planned parts.
TEST(UnseenAreaRepair, PlansOfTheHardMapsSeeTheirReachableArea) {
  for (const testing::MapFamily family : testing::HardMapGenerator::families()) {
    const testing::HardMapGenerator generator(family);
    const bool shoreline = testing::HardMapGenerator::name(family) == "shoreline";
    for (int seed : shoreline ? std::vector<int>{2, 3} : std::vector<int>{0, 1, 2, 3, 4}) {
      const testing::HardMap map = generator.generate(static_cast<std::uint64_t>(seed));
      const std::string name =
          testing::HardMapGenerator::name(family) + " seed " + std::to_string(seed);
      const PlannedBothWays plans = planBothWays(map.mission);
      const PlannedMission& planned = plans.without;
      const PlannedMission& repaired = plans.with;
      const std::vector<Point2>& before = plans.before;
      const std::vector<Point2>& after = plans.after;
      const double wall_distance = map.mission.parameters.wall_distance;
      const CoverageEvaluator evaluator(
          repaired.free_area,
          exactOffsetParts(repaired.free_area, wall_distance, repaired.plan.offset_parts),
          plans.sensor, reportingResolution(), kReportingGridAngle);
      const CoverageReport report_before =
          evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(before)));
      const CoverageReport report_after =
          evaluator.report(evaluator.seeWaypointPath(legHeadingPoses(after)));
      EXPECT_LE(report_after.unseen_reachable_area_m2, report_before.unseen_reachable_area_m2)
          << name;
      EXPECT_GE(report_after.reachable_coverage_percent, 99.9) << name;
      EXPECT_EQ(after.front(), before.front()) << name;
      EXPECT_EQ(after.back(), before.back()) << name;
      // Legs run in the route area, or out of it to the exact offset (an excursion),
      // keeping the wall distance.
      for (std::size_t i = repaired.plan.first_inside; i < repaired.plan.last_inside; ++i) {
        EXPECT_TRUE(segmentInside(repaired.plan.route_area, after[i], after[i + 1], 1e-6) ||
                    keepsClearance(
                        testing::sampledWallDistance(repaired.free_area, {after[i], after[i + 1]}),
                        wall_distance))
            << name << " leg " << i;
      }
      EXPECT_GE(repaired.plan.time_cost_s, planned.plan.time_cost_s - 1e-9) << name;
      const auto hasRepairStage = [](const CoveragePlan& plan) {
        for (const PlanningStage& stage : plan.stages) {
          if (stage.name == "repair") return true;
        }
        return false;
      };
      EXPECT_TRUE(hasRepairStage(repaired.plan)) << name;
      EXPECT_FALSE(hasRepairStage(planned.plan)) << name;
    }
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
