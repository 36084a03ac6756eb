#include "coverage_system/planner/coverage_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/lazy_transition_costs.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "test/planner/plan_properties.h"
#include "test/support/hard_map_generator.h"
#include "test/support/random_polygons.h"
#include "test/support/test_shapes.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {
namespace {

const PolygonWithHoles kLake = {
    {{0, 0}, {30, 0}, {30, 30}, {0, 30}},
    {{{7, 9}, {7, 15}, {12, 15}, {12, 9}}, {{18, 17}, {16, 21}, {19, 25}, {24, 23}, {23, 18}}}};

TEST(CoveragePlanner, LakeMissionPlanIsValid) {
  const PlannerParameters parameters;
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kLake, {0.5, 5}, {29, 29});
  expectValidPlan(kLake, plan, parameters, {0.5, 5}, {29, 29});
  EXPECT_GE(plan.cells.size(), 3u);
  EXPECT_GT(plan.time_cost_s, plan.path_length_m / parameters.v_max);
  EXPECT_EQ(plan.first_inside, 1u);                        // (0.5, 5) is in the 1 m wall band
  EXPECT_EQ(plan.last_inside, plan.waypoints.size() - 1);  // (29, 29): the offset corner
  ASSERT_FALSE(plan.stages.empty());
}

/// Three rooms in a row, 20, 14 and 10 m, joined by straits 1.5 m and 1.2 m wide: with a
/// 1 m wall distance the offset free area falls into three parts.
const PolygonWithHoles kThreeRooms = {
    {{0, 0},    {20, 0},  {20, 9.25},  {22, 9.25},  {22, 3},  {36, 3},    {36, 9.4},
     {38, 9.4}, {38, 5},  {48, 5},     {48, 15},    {38, 15}, {38, 10.6}, {36, 10.6},
     {36, 17},  {22, 17}, {22, 10.75}, {20, 10.75}, {20, 20}, {0, 20}},
    {}};

TEST(CoveragePlanner, EveryPartOfASplitOffsetAreaIsPlannedAndSeen) {
  PlannerParameters parameters;
  parameters.sensor_distance = 1.0;  // W = 4.27 m, L = 0.53 m
  parameters.gap_clearance = 0.5;    // transits may pass the straits (0.6 and 0.75 m)
  // Start in the smallest room, goal in the largest: the robot passes both straits.
  const Point2 start(40, 6);
  const Point2 goal(18, 18);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kThreeRooms, start, goal);
  expectValidPlan(kThreeRooms, plan, parameters, start, goal);
  ASSERT_EQ(plan.offset_parts.size(), 3u);
  EXPECT_EQ(plan.gaps.size(), 2u);
  EXPECT_EQ(plan.warnings.size(), 2u);  // one per gap, with its place and clearance
  for (const std::string& warning : plan.warnings) {
    EXPECT_NE(warning.find("m clearance, nearer than wall_distance 1 m (gap_clearance 0.5 m "
                           "allows it)"),
              std::string::npos)
        << warning;
  }
  for (const PolygonWithHoles& part : plan.offset_parts) {
    std::size_t inside = 0;
    for (const Pose2& waypoint : plan.waypoints)
      inside += contains(part, waypoint.position(), 1e-6);
    EXPECT_GE(inside, 4u) << "part near " << part.hull.front().transpose();
  }
  for (const bool smoothing : {false, true}) {
    parameters.smoothing = smoothing;
    const GeneratedTrajectory trajectory =
        TrajectoryGenerator(trajectoryOptionsOf(parameters)).generate(plan.waypoints, kThreeRooms);
    std::vector<Pose2> poses;
    for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
    const TrajectoryCoverage coverage =
        measureTrajectoryCoverage(kThreeRooms, plan.exact_offset_parts, parameters, poses);
    EXPECT_GE(coverage.report.reachable_coverage_percent, 99.0) << "smoothing " << smoothing;
    // The transits keep 86 % of the straits' clearance (0.6 m and 0.75 m); the smoother
    // (whose contract is no collision) may turn into a strait's mouth closer to its corner
    // (0.41 m).
    EXPECT_GT(trajectory.min_obstacle_clearance_m, smoothing ? 0.3 : 0.5)
        << "smoothing " << smoothing;
  }
}

TEST(CoveragePlanner, ByDefaultPartsBeyondStraitsNarrowerThanTwoWallDistancesAreNotEntered) {
  PlannerParameters parameters;
  parameters.sensor_distance = 1.0;
  // From the smallest room: both larger rooms lie beyond a strait narrower than 2 m.
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kThreeRooms, {40, 6}, {46, 14});
  expectValidPlan(kThreeRooms, plan, parameters, {40, 6}, {46, 14});
  ASSERT_EQ(plan.offset_parts.size(), 1u);
  EXPECT_TRUE(plan.gaps.empty());
  for (const Pose2& waypoint : plan.waypoints) EXPECT_GE(waypoint.x, 38.0);
  // The two rooms not entered, for plot.png and rviz: left of the start's room.
  ASSERT_EQ(plan.unreachable_parts.size(), 2u);
  for (const PolygonWithHoles& part : plan.unreachable_parts) {
    for (const Point2& p : part.hull) EXPECT_LT(p.x(), 38.0);
  }
  ASSERT_EQ(plan.warnings.size(), 2u);
  for (const std::string& warning : plan.warnings) {
    EXPECT_NE(warning.find("is not entered (it counts as unreachable): the widest gap to it"),
              std::string::npos)
        << warning;
    // Both rooms' widest passage is the 1.2 m strait beside the start's room.
    EXPECT_NE(warning.find("m clearance, below gap_clearance 1 m"), std::string::npos) << warning;
  }
  // A goal in a room the robot cannot reach is refused, naming the passage.
  try {
    CoveragePlanner(parameters).plan(kThreeRooms, {40, 6}, {10, 10});
    ADD_FAILURE() << "a goal beyond a strait narrower than gap_clearance was planned";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("goal (10, 10) lies in a part of "), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("that the robot cannot reach from the start"),
              std::string::npos)
        << error.what();
  }
}

TEST(CoveragePlanner, AStraitOfTwiceTheWallDistanceIsPassedKeepingTheWallDistance) {
  // The mitred offset splits at the strait, but a robot keeping 1 m passes along its
  // middle, and by default it does, unwarned.
  const PolygonWithHoles free_area = testing::twoRoomsJoinedByATwoMetreStrait();
  PlannerParameters parameters;
  parameters.sensor_distance = 1.0;
  const CoveragePlan plan = CoveragePlanner(parameters).plan(free_area, {2, 2}, {24, 8});
  expectValidPlan(free_area, plan, parameters, {2, 2}, {24, 8});
  EXPECT_EQ(plan.offset_parts.size(), 2u);
  ASSERT_EQ(plan.gaps.size(), 1u);
  EXPECT_TRUE(plan.warnings.empty()) << plan.warnings.front();
  for (const bool smoothing : {false, true}) {
    parameters.smoothing = smoothing;
    const GeneratedTrajectory trajectory =
        TrajectoryGenerator(trajectoryOptionsOf(parameters, plan.exact_offset_parts))
            .generate(plan.waypoints, free_area);
    EXPECT_TRUE(keepsClearance(trajectory.min_obstacle_clearance_m, 1.0))
        << "smoothing " << smoothing << ": " << trajectory.min_obstacle_clearance_m;
  }
}

TEST(CoveragePlanner, OffsetPartsLargestPlansOnlyTheLargestPartAndNamesTheOthers) {
  PlannerParameters parameters;
  parameters.sensor_distance = 1.0;
  parameters.offset_parts = "largest";
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kThreeRooms, {2, 2}, {18, 18});
  ASSERT_EQ(plan.offset_parts.size(), 3u);
  EXPECT_TRUE(plan.gaps.empty());
  EXPECT_NEAR(area(plan.route_area), area(plan.offset_parts.front()), 1e-9);
  ASSERT_EQ(plan.warnings.size(), 2u);
  for (const std::string& warning : plan.warnings) {
    EXPECT_NE(warning.find("is not planned (offset_parts: largest)"), std::string::npos) << warning;
  }
  for (const Pose2& waypoint : plan.waypoints) EXPECT_LE(waypoint.x, 20.0);
}

TEST(CoveragePlanner, AGoalInANarrowBayIsJoinedAlongTheBayNotThroughItsWall) {
  // A 1.2 m bay (narrower than two wall distances) beside a 6 m one, a wall 0.3 m thick
  // between them: the nearest point of the offset free area to a goal deep in the narrow
  // bay lies across the wall; the leg goes out of the bay instead.
  const PolygonWithHoles comb = {{{0, 0},
                                  {30, 0},
                                  {30, 10},
                                  {12.5, 10},
                                  {12.5, 20},
                                  {6.5, 20},
                                  {6.5, 10},
                                  {6.2, 10},
                                  {6.2, 20},
                                  {5, 20},
                                  {5, 10},
                                  {0, 10}},
                                 {}};
  const PlannerParameters parameters;
  const Point2 goal(5.6, 18);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(comb, {2, 2}, goal);
  expectValidPlan(comb, plan, parameters, {2, 2}, goal);
  ASSERT_EQ(plan.last_inside, plan.waypoints.size() - 2);
  const Point2 entry = plan.waypoints[plan.last_inside].position();
  EXPECT_TRUE(segmentInside(comb, entry, goal)) << entry.transpose();
  EXPECT_NEAR(entry.x(), 5.6, 1e-9);
  EXPECT_NEAR(entry.y(), 9.0, 1e-9);
}

/// The parameters of a planner_fuzzer finding: a trapezoidal decomposition and the frustum
/// sensor's fuzzed values.
PlannerParameters fuzzedParameters(double wall_distance, double sensor_distance, double lateral_fov,
                                   double onward_fov, double lateral_overlap,
                                   double turning_radius) {
  PlannerParameters parameters;
  parameters.wall_distance = wall_distance;
  parameters.sensor_distance = sensor_distance;
  parameters.lateral_fov = lateral_fov;
  parameters.onward_fov = onward_fov;
  parameters.lateral_overlap = lateral_overlap;
  parameters.turning_radius = turning_radius;
  parameters.decomposition_type = "trapezoidal";
  return parameters;
}

TEST(CoveragePlanner, LanesThroughAcuteCornersEndInsideTheOffsetArea) {
  // Found by planner_fuzzer (its seed corpus input seed_01): a footprint longer than wide
  // (W 0.72 m, L 2.70 m) on a 9-vertex hull whose offset has acute corners. Lanes placed
  // through those corners ended 1e-8 m beyond them, outside the offset free area, and the
  // sweeps stage failed on valid input.
  const PolygonWithHoles hull = {{{28.5, 17.5},
                                  {17.5, 17.5},
                                  {14, 26.5},
                                  {2.5, 26.5},
                                  {13, 15.5},
                                  {13, 14.5},
                                  {14, 13.5},
                                  {15.5, 13},
                                  {16.5, 13.5}},
                                 {}};
  const PlannerParameters parameters =
      fuzzedParameters(1.7462979108529295, 0.65372509748196106, 1.010946912328647,
                       2.2437657091353485, 0.72074031980502995, 4.7983420811323896);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(hull, {-5, -5}, {-5, -5});
  expectValidPlan(hull, plan, parameters, {-5, -5}, {-5, -5});
}

TEST(CoveragePlanner, ASmallOffsetAreaFarFromTheOriginKeepsItsLaneEndsInside) {
  // Found by planner_fuzzer: the offset free area is 0.55 m across at (15, 15). The route
  // stage's tolerance followed the area's extent only (5.5e-10 m), less than the rounding
  // that the cells carry at coordinates of 15 m, so a lane end on a cell's corner lay
  // "outside the area" and the transitions stage failed on valid input.
  const PolygonWithHoles hull = {{{20.874691964009198, 15.708343402335082},
                                  {21.184039707702244, 18.886425283785073},
                                  {15.999999985992337, 16.732050815656205},
                                  {15, 17},
                                  {14, 16.73205080756888},
                                  {13.267949192431123, 16},
                                  {13, 15},
                                  {13.267949192431121, 14},
                                  {14, 13.267949192431123},
                                  {15, 13},
                                  {15.999999999999998, 13.267949192431121},
                                  {16.732050807568875, 14}},
                                 {}};
  const PlannerParameters parameters =
      fuzzedParameters(1.747009277346526, 0.9457667617297865, 1.1864368056340127,
                       2.0866980950750476, 0.8241383538584348, 1.8709583598561028);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(hull, {-5, -5}, {-5, -5});
  expectValidPlan(hull, plan, parameters, {-5, -5}, {-5, -5});
}

TEST(CoveragePlanner, TransitionsBetweenLaneEndsNearAConvexCornerAreFinite) {
  // Found by planner_fuzzer: an offset free area 0.57 m across, whose cell has a lane
  // 1.3e-7 m long at a corner; the route stage refused the chord between its ends, and the
  // solve stage met an infinite transition cost.
  const PolygonWithHoles hull = {{{28.5, 17.5},
                                  {16.5, 16.5},
                                  {15.5, 17},
                                  {14, 16.5},
                                  {13, 15.5},
                                  {13, 14.5},
                                  {14, 13.5},
                                  {15.5, 13},
                                  {16.5, 13.5}},
                                 {}};
  const PlannerParameters parameters =
      fuzzedParameters(1.7462979108529295, 0.6537250974819611, 1.010946912328647,
                       2.2437657091353485, 0.72074031980503, 4.79834208113239);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(hull, {-5, -5}, {-5, -5});
  expectValidPlan(hull, plan, parameters, {-5, -5}, {-5, -5});
}

TEST(CoveragePlanner, TransitionsAlongAnEdgePastAConvexCornerAreFinite) {
  // Found by planner_fuzzer: a lane end just past a corner of the offset free area, on the
  // next edge, and another at the far end of the edge before it; the route stage refused
  // the transition between them and the solve stage met an infinite cost.
  const PolygonWithHoles hull = {{{30.608537836557257, 22.13686274150293},
                                  {15, 17},
                                  {8.572093340119306, 11.9318255814334},
                                  {20.20407070343419, 4.048520334254395}},
                                 {}};
  const PlannerParameters parameters =
      fuzzedParameters(1.7462979108529295, 0.6537250974819611, 1.010946912328647,
                       1.5074375841353487, 0.72074031980503, 4.79834208113239);
  const Point2 start(-4.9999999999999964, -5);
  const CoveragePlan plan = CoveragePlanner(parameters).plan(hull, start, {-5, -5});
  expectValidPlan(hull, plan, parameters, start, {-5, -5});
}

TEST(CoveragePlanner, StartOutsideTheHullIsJoinedByAStraightLeg) {
  const PlannerParameters parameters;
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kLake, {-10, 15}, {15, 40});
  expectValidPlan(kLake, plan, parameters, {-10, 15}, {15, 40});
  EXPECT_EQ(plan.first_inside, 1u);
  EXPECT_NEAR(plan.waypoints[1].x, 1.0, 1e-9);
  EXPECT_NEAR(plan.waypoints[1].y, 15.0, 1e-9);
  EXPECT_EQ(plan.last_inside, plan.waypoints.size() - 2);
}

TEST(CoveragePlanner, GoalJustOutsideTheOffsetAreaIsTheLastWaypoint) {
  // Found by planner_fuzzer: a goal closer to its entry point than the duplicate tolerance
  // was merged into it, so the path ended at the entry point instead of the goal.
  const PlannerParameters parameters;
  const Point2 goal(29.0 + 1e-7, 29.0);  // (29, 29) is the nearest offset corner
  const CoveragePlan plan = CoveragePlanner(parameters).plan(kLake, {0.5, 5}, goal);
  expectValidPlan(kLake, plan, parameters, {0.5, 5}, goal);
  ASSERT_FALSE(plan.waypoints.empty());
  EXPECT_EQ(plan.waypoints.back().position(), goal);
  EXPECT_EQ(plan.last_inside, plan.waypoints.size() - 2);
}

TEST(CoveragePlanner, StartInsideAHoleIsRejected) {
  const CoveragePlanner planner{PlannerParameters{}};
  try {
    planner.plan(kLake, {9, 10}, {29, 29});
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("start (9, 10) lies inside hole 0"), std::string::npos)
        << error.what();
  }
}

TEST(CoveragePlanner, EntryLegThroughAHoleIsRejected) {
  // A hole hugging the hull's left wall: from outside, the nearest point of the offset
  // area lies behind it.
  const PolygonWithHoles area = {{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                                 {{{0.5, 3}, {0.5, 27}, {5, 27}, {5, 3}}}};
  const CoveragePlanner planner{PlannerParameters{}};
  EXPECT_THROW(planner.plan(area, {-5, 15}, {29, 29}), InvalidInputError);
}

TEST(CoveragePlanner, EmptyOffsetAreaIsRejected) {
  const PolygonWithHoles narrow = {{{0, 0}, {30, 0}, {30, 1.5}, {0, 1.5}}, {}};
  EXPECT_THROW(CoveragePlanner{PlannerParameters{}}.plan(narrow, {1, 1}, {2, 1}),
               InvalidInputError);
}

/// The message of the InvalidInputError that planning `area` throws ("" when none).
std::string refusal(const PlannerParameters& parameters, const PolygonWithHoles& area,
                    const Point2& start, const Point2& goal) {
  try {
    CoveragePlanner(parameters).plan(area, start, goal);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

TEST(CoveragePlanner, TooManySweepLanesAreRefusedBeforeAnyLaneIsPlaced) {
  // A 2 km square under a 1 cm footprint: two kept lane directions (its sides) of 333 000
  // lanes each. Refused right after the decomposition, so the test takes milliseconds.
  const PolygonWithHoles square = {{{0, 0}, {2000, 0}, {2000, 2000}, {0, 2000}}, {}};
  PlannerParameters line;
  line.sensor_model = "line";
  line.lateral_footprint = 0.01;
  const std::string message = refusal(line, square, {1, 1}, {1999, 1999});
  EXPECT_NE(message.find("the cells need at least 666000 sweep lanes, 646000 more than the limit "
                         "of " +
                         std::to_string(kMaxSweeps)),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("sweep distance of 0.006 m"), std::string::npos) << message;
  EXPECT_NE(message.find("grow about 33.3 times"), std::string::npos) << message;
  EXPECT_NE(message.find("a larger lateral_footprint"), std::string::npos) << message;

  // A frustum sensor 5 mm above the bottom: the message names the frustum's parameters.
  PlannerParameters frustum;
  frustum.sensor_distance = 0.005;
  const std::string frustum_message = refusal(frustum, square, {1, 1}, {1999, 1999});
  EXPECT_NE(frustum_message.find("a larger sensor_distance"), std::string::npos) << frustum_message;
  EXPECT_NE(frustum_message.find("lateral_overlap"), std::string::npos) << frustum_message;
}

TEST(CoveragePlanner, AMapOverMaxMemoryIsRefusedRightAfterTheDecomposition) {
  // A comb of 1 100 teeth, 3 m wide and 3 m apart: one cell per tooth and the base, over
  // 100 MB by the estimate (no fixed cell count refuses it). No wall offset: the refusal
  // comes right after the decomposition either way.
  constexpr int kTeeth = 1100;
  const double width = 6.0 * kTeeth - 3.0;
  Ring hull = {{0, 0}, {width, 0}};
  for (int i = kTeeth - 1; i >= 0; --i) {
    const double left = 6.0 * i;
    if (i < kTeeth - 1) hull.emplace_back(left + 3.0, 10.0);
    hull.emplace_back(left + 3.0, 20.0);
    hull.emplace_back(left, 20.0);
    if (i > 0) hull.emplace_back(left, 10.0);
  }
  const PolygonWithHoles comb = {hull, {}};
  for (const char* type : {"boustrophedon", "trapezoidal"}) {
    PlannerParameters parameters;
    parameters.decomposition_type = type;
    parameters.cell_joining = "critical_points";  // joined: the base goes on into one tooth
    parameters.wall_distance = 0.0;
    parameters.max_memory_mb = 100.0;
    const std::string message = refusal(parameters, comb, {1, 1}, {width - 1, 1});
    SCOPED_TRACE(type);
    EXPECT_NE(message.find("MB, more than max_memory_mb 100 MB (1101 cells with "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("simplify the polygon"), std::string::npos) << message;
    EXPECT_EQ(message.find("makes fewer cells") != std::string::npos,
              std::string(type) == "trapezoidal")
        << message;
  }
}

TEST(CoveragePlanner, AllCostFunctionsAndDecompositions) {
  for (const char* cost : {"distance", "time", "waypoints"}) {
    for (const char* decomposition : {"boustrophedon", "trapezoidal"}) {
      PlannerParameters parameters;
      parameters.cost_function = cost;
      parameters.decomposition_type = decomposition;
      SCOPED_TRACE(std::string(cost) + " " + decomposition);
      const CoveragePlan plan = CoveragePlanner(parameters).plan(kLake, {1, 1}, {29, 29});
      expectValidPlan(kLake, plan, parameters, {1, 1}, {29, 29});
    }
  }
}

/// The stage line of `name`, or "" when the plan has none.
std::string stageSummary(const CoveragePlan& plan, const std::string& name) {
  for (const PlanningStage& stage : plan.stages) {
    if (stage.name == name) return stage.summary;
  }
  return "";
}

/// Cells joined across critical points on a small map: Choset's cells are planned too and
/// the cheaper tour is kept, so the plan never costs more than with Choset's cells alone.
TEST(CoveragePlanner, JoinedCellsNeverCostMoreOnASmallMap) {
  PlannerParameters choset_parameters;
  choset_parameters.smoothing = false;
  choset_parameters.cell_joining = "critical_points";
  PlannerParameters joined_parameters = choset_parameters;
  joined_parameters.cell_joining = "longest_overlap";
  for (const auto& [start, goal] : {std::pair<Point2, Point2>{{1, 1}, {29, 29}},
                                    std::pair<Point2, Point2>{{0.5, 5}, {15, 29}}}) {
    const CoveragePlan choset = CoveragePlanner(choset_parameters).plan(kLake, start, goal);
    const CoveragePlan joined = CoveragePlanner(joined_parameters).plan(kLake, start, goal);
    expectValidPlan(kLake, joined, joined_parameters, start, goal);
    EXPECT_LE(joined.time_cost_s, choset.time_cost_s * (1.0 + 1e-12));
    EXPECT_EQ(stageSummary(choset, "alternative"), "");
    EXPECT_NE(stageSummary(joined, "alternative").find("Choset's"), std::string::npos);
  }
}

/// A noisy shoreline (HardMapGenerator's family, 316 vertices): Choset's cells multiply with
/// the bays, lanes of neighbouring cells do not line up and the tour revisits the water
/// beside them; joined across critical points the open water stays in few long cells. The
/// joined plan has under half the cells, costs under 60 % of Choset's (0.53 when measured),
/// stays in the offset free area and sees all of the reachable area but 0.1 %.
TEST(CoveragePlanner, AGeneralizedTspStoppedAtItsSafetyCapIsReported) {
  const testing::HardMap map =
      testing::HardMapGenerator(testing::MapFamily::kShoreline).generate(46);
  PlannerParameters parameters = map.mission.parameters;
  parameters.smoothing = false;
  PlanningOptions options = planningOptionsOf(parameters);
  const CoveragePlan full =
      CoveragePlanner(options).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  EXPECT_FALSE(full.gtsp_time_capped);
  ASSERT_GT(full.cells.size(), 14u);  // solved by the heuristic, which has the cap
  options.gtsp_time_limit_s = 1e-9;
  const CoveragePlan capped =
      CoveragePlanner(options).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  expectValidPlan(map.mission.polygon, capped, parameters, map.mission.start, map.mission.goal);
  EXPECT_TRUE(capped.gtsp_time_capped);
  EXPECT_NE(stageSummary(capped, "solve").find("stopped at the safety cap"), std::string::npos);
  std::size_t cap_warnings = 0;
  for (const std::string& warning : capped.warnings) {
    if (warning.find("safety cap") != std::string::npos) ++cap_warnings;
  }
  EXPECT_EQ(cap_warnings, 1u);
}

TEST(CoveragePlanner, JoinedCellsCoverANoisyShorelineInFewerCellsAndLessTime) {
  const testing::HardMap map =
      testing::HardMapGenerator(testing::MapFamily::kShoreline).generate(46);
  PlannerParameters parameters = map.mission.parameters;
  parameters.smoothing = false;
  parameters.decomposition_type = "boustrophedon";
  parameters.cell_joining = "critical_points";
  parameters.boundary_simplification = 0.0;  // the cells of the exact boundary
  const CoveragePlan choset =
      CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  parameters.cell_joining = "longest_overlap";
  const CoveragePlan joined =
      CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  expectValidPlan(map.mission.polygon, joined, parameters, map.mission.start, map.mission.goal);
  EXPECT_GT(choset.cells.size(), 50u);
  EXPECT_LT(2 * joined.cells.size(), choset.cells.size());
  EXPECT_LT(joined.time_cost_s, 0.6 * choset.time_cost_s);
  EXPECT_NE(stageSummary(joined, "alternative").find("not planned"), std::string::npos);
  const GeneratedTrajectory trajectory = TrajectoryGenerator(trajectoryOptionsOf(parameters))
                                             .generate(joined.waypoints, map.mission.polygon);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
  const TrajectoryCoverage coverage =
      measureTrajectoryCoverage(map.mission.polygon, joined.exact_offset_parts, parameters, poses);
  EXPECT_GE(coverage.report.reachable_coverage_percent, 99.9);
}

/// The reachable coverage of the trajectory the default smoothing makes of the plan.
double trajectoryReachableCoverage(const testing::HardMap& map, const PlannerParameters& parameters,
                                   const CoveragePlan& plan) {
  PlannerParameters smoothed = parameters;
  smoothed.smoothing = true;
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(trajectoryOptionsOf(smoothed, plan.exact_offset_parts))
          .generate(plan.waypoints, map.mission.polygon);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
  return measureTrajectoryCoverage(map.mission.polygon, plan.exact_offset_parts, smoothed, poses)
      .report.reachable_coverage_percent;
}

/// A 500-vertex lake chart with 10 islands: decomposed with its offset boundary simplified
/// within 5 % of the sweep distance, it has fewer cells, its legs stay in the exact offset
/// free area, its smoothed trajectory sees at least 99.9 % of the reachable area, and its
/// tour costs no more than with the exact boundary (0.5 % allowed).
TEST(CoveragePlanner, ASimplifiedBoundaryPlansAChartInFewerCellsAndSeesItsRim) {
  const testing::HardMap map = testing::HardMapGenerator::lakeChart(0, 500, 10);
  PlannerParameters parameters = map.mission.parameters;
  parameters.smoothing = false;
  parameters.boundary_simplification = 0.0;
  const CoveragePlan exact =
      CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  EXPECT_EQ(stageSummary(exact, "simplify"), "");
  parameters.boundary_simplification = 0.05;
  const CoveragePlan simplified =
      CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  expectValidPlan(map.mission.polygon, simplified, parameters, map.mission.start, map.mission.goal);
  EXPECT_NE(stageSummary(simplified, "simplify").find("vertices"), std::string::npos);
  EXPECT_LT(simplified.cells.size(), exact.cells.size());
  EXPECT_LE(simplified.time_cost_s, 1.005 * exact.time_cost_s);
  EXPECT_GE(trajectoryReachableCoverage(map, parameters, simplified), 99.9);
}

/// The first shorelines of HardMapGenerator's family, simplified within a tenth of the sweep
/// distance: valid plans (legs in the exact offset free area, the reachable area seen) whose
/// smoothed trajectories see at least 99.9 % of the reachable area.
TEST(CoveragePlanner, SimplifiedShorelinesPlanValidlyAndSeeTheReachableArea) {
  const testing::HardMapGenerator generator(testing::MapFamily::kShoreline);
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const testing::HardMap map = generator.generate(seed);
    SCOPED_TRACE(::testing::Message() << "shoreline seed " << seed);
    PlannerParameters parameters = map.mission.parameters;
    parameters.smoothing = false;
    parameters.boundary_simplification = 0.1;
    const CoveragePlan plan =
        CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
    expectValidPlan(map.mission.polygon, plan, parameters, map.mission.start, map.mission.goal);
    EXPECT_GE(trajectoryReachableCoverage(map, parameters, plan), 99.9);
  }
}

/// Shoreline seed 26: the mitred offset closes the neck to a part of 900 m^2 (its mitres
/// meet where the gap keeps 1.50 m, below the wall distance of 1.52 m), while the points at
/// least the wall distance from the walls pass it. The gap is found on the exact offset,
/// and the part is entered and seen. With the mitres squared off, a pocket of 0.01 m^2
/// behind a 1.10 m gap lies nearest the start, 1.02 m from the shore: the start reaches the
/// main part without coming nearer the shore, and the pocket is the part left out.
TEST(CoveragePlanner, APartBeyondANeckThatOnlyTheMitredOffsetClosesIsEntered) {
  const testing::HardMap map =
      testing::HardMapGenerator(testing::MapFamily::kShoreline).generate(26);
  PlannerParameters parameters = map.mission.parameters;
  parameters.smoothing = false;
  const CoveragePlan plan =
      CoveragePlanner(parameters).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  expectValidPlan(map.mission.polygon, plan, parameters, map.mission.start, map.mission.goal);
  EXPECT_GT(area(plan.offset_parts), 900.0);
  EXPECT_LT(area(plan.unreachable_parts), 1.0);
  EXPECT_GE(trajectoryReachableCoverage(map, parameters, plan), 99.9);
}

/// The planner's guarantee: on 200 seeded random maps (hulls 50 to 200 m across, 0 to 15 holes,
/// footprints from 12.9 m down to 2 m), every leg lies in the offset free area and the
/// footprints swept along the legs cover at least 99 % of the reachable area.
TEST(CoveragePlanner, RandomMapsAreCoveredInsideTheOffsetArea) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> size(50.0, 200.0);
  std::uniform_real_distribution<double> footprint_width(2.0, 12.9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int planned = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double map_size = size(rng);
    const PolygonWithHoles map = testing::randomMap(rng, map_size, 15, 2.5);
    PlannerParameters parameters;
    // Choose the sensor distance that gives the wanted footprint width.
    const double width = footprint_width(rng);
    parameters.sensor_distance = width / (2.0 * std::tan(0.5 * parameters.lateral_fov));
    parameters.wall_distance = 0.5 + unit(rng);
    parameters.lateral_overlap = 0.2 + 0.4 * unit(rng);
    // Start and goal near two hull vertices, out of every hole.
    const Point2 start = testing::freePointNear(map, map.hull[0]);
    const Point2 goal = testing::freePointNear(map, map.hull[map.hull.size() / 2]);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " size " << map_size << " holes "
                                      << map.holes.size() << " width " << width);
    CoveragePlan plan;
    try {
      plan = CoveragePlanner(parameters).plan(map, start, goal);
    } catch (const InvalidInputError& error) {
      // A start or goal behind a hole is a legitimate rejection; nothing else is.
      EXPECT_NE(std::string(error.what()).find("crosses a hole"), std::string::npos)
          << error.what();
      continue;
    }
    ++planned;
    expectValidPlan(map, plan, parameters, start, goal);
  }
  EXPECT_GE(planned, 180);
}

// The paths for charts of thousands of cells, reached on a lake chart by lowering their
// thresholds: transitions routed between nearby cells only (the others estimated until a
// tour uses them) and a visibility graph searched on demand give a valid plan that sees
// what the all-pairs one sees, at a time cost within 2 % of it.
TEST(CoveragePlanner, LazyTransitionsAndOnDemandRoutesPlanAsTheAllPairsOnesDo) {
  const testing::HardMap map = testing::HardMapGenerator::lakeChart(0, 500, 10);
  PlannerParameters parameters = map.mission.parameters;
  parameters.smoothing = false;
  PlanningOptions options = planningOptionsOf(parameters);
  const CoveragePlan dense =
      CoveragePlanner(options).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  options.dense_transition_nodes = 0;
  options.dense_route_corners = 0;
  const CoveragePlan lazy =
      CoveragePlanner(options).plan(map.mission.polygon, map.mission.start, map.mission.goal);
  expectValidPlan(map.mission.polygon, lazy, parameters, map.mission.start, map.mission.goal);
  EXPECT_NE(stageSummary(lazy, "transitions").find("routed, between nearby cells"),
            std::string::npos);
  EXPECT_EQ(stageSummary(dense, "transitions").find("nearby"), std::string::npos);
  ASSERT_GT(lazy.cells.size(), LazyTransitionCosts::kCandidateCells + 1u);
  EXPECT_LE(lazy.time_cost_s, 1.02 * dense.time_cost_s);
  EXPECT_GE(lazy.time_cost_s, 0.98 * dense.time_cost_s);
  EXPECT_FALSE(lazy.gtsp_time_capped);
}

}  // namespace
}  // namespace kinematic_coverage::core
