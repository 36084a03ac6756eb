// The coverage bars of coverage-safe smoothing over CI's slice of the hard map families
// (test/support/hard_map_generator.h, the first five maps of each; docs/BENCHMARKS.md,
// Smoothing strategies on the hard maps): planned once as `coverage_tool plan` does, the
// coverage-safe trajectory sees the reachable area within 0.05 points of the unsmoothed
// trajectory of the same plan, and at least 99.9 % of it wherever the unsmoothed one sees
// that much with the 0.05 points to spare; and it keeps the wall distance (within
// kClearanceTolerance) wherever the unsmoothed trajectory does, and never comes nearer the
// walls than that one (which passes gaps narrower than two wall distances).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/hard_map_generator.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {
namespace {

constexpr int kMapsPerFamily = 5;
/// Share (%) of the reachable area a trajectory must see (the product's bar).
constexpr double kBarPercent = 99.9;
/// Points of the reachable area that coverage-safe smoothing may see less of.
constexpr double kMaxDropPoints = 0.05;

/// What the bars measure of one trajectory.
struct Measured {
  double reachable_percent = 0.0;  ///< reachable coverage
  double clearance_m = 0.0;        ///< min_obstacle_clearance_m
};

/// The trajectory that `parameters` make of `planned`, measured.
Measured measure(const PlannedMission& planned, const PlannerParameters& parameters) {
  const GeneratedTrajectory trajectory = TrajectoryGenerator(trajectoryOptionsOf(parameters))
                                             .generate(planned.plan.waypoints, planned.free_area);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
  return {measureTrajectoryCoverage(planned.free_area, planned.plan.exact_offset_parts, parameters,
                                    poses)
              .report.reachable_coverage_percent,
          trajectory.min_obstacle_clearance_m};
}

/// A smoothed trajectory keeps the wall distance, or comes no nearer than the unsmoothed.
void expectClearanceKept(const Measured& smoothed, const Measured& sharp, double wall_distance,
                         const std::string& name) {
  EXPECT_GE(smoothed.clearance_m, std::min(wall_distance - kClearanceTolerance, sharp.clearance_m))
      << name << ": " << smoothed.clearance_m << " m against " << sharp.clearance_m
      << " m unsmoothed, wall_distance " << wall_distance << " m";
}

/// Plans `seed` of `family` and expects its coverage-safe trajectory to keep the bars.
void expectBarsKept(testing::MapFamily family, int seed) {
  const testing::HardMap map =
      testing::HardMapGenerator(family).generate(static_cast<std::uint64_t>(seed));
  const std::string name =
      testing::HardMapGenerator::name(family) + " seed " + std::to_string(seed);
  const PlannedMission planned = planMission(map.mission);
  PlannerParameters unsmoothed = map.mission.parameters;
  unsmoothed.smoothing = false;
  PlannerParameters safe = map.mission.parameters;
  safe.smoothing = true;
  safe.smoothing_strategy = "coverage_safe";
  const Measured sharp = measure(planned, unsmoothed);
  const double sharp_percent = sharp.reachable_percent;
  const Measured safe_run = measure(planned, safe);
  const double safe_percent = safe_run.reachable_percent;
  EXPECT_GE(safe_percent, sharp_percent - kMaxDropPoints) << name;
  if (sharp_percent >= kBarPercent + kMaxDropPoints) EXPECT_GE(safe_percent, kBarPercent) << name;
  const double wall_distance = map.mission.parameters.wall_distance;
  expectClearanceKept(safe_run, sharp, wall_distance, name);
  // Continuous-curvature turns keep the bars too: each loses no more than its arc.
  PlannerParameters clothoid = safe;
  clothoid.turn_curve = "clothoid";
  const Measured clothoid_run = measure(planned, clothoid);
  const double clothoid_percent = clothoid_run.reachable_percent;
  EXPECT_GE(clothoid_percent, sharp_percent - kMaxDropPoints) << name;
  if (sharp_percent >= kBarPercent + kMaxDropPoints) {
    EXPECT_GE(clothoid_percent, kBarPercent) << name;
  }
  expectClearanceKept(clothoid_run, sharp, wall_distance, name);
}

TEST(CoverageSafeBars, EveryFamilysFirstMapsKeepWhatTheUnsmoothedTrajectorySees) {
  for (const testing::MapFamily family : testing::HardMapGenerator::families()) {
    for (int seed = 0; seed < kMapsPerFamily; ++seed) expectBarsKept(family, seed);
  }
}

// Its joined cells sweep two corridors across in short lanes: 60 reverse curves, each
// cutting a little of the reachable area's rim along the corridor walls. The whole-path
// check once measured that rim on a grown raster mask, half a cell off the report's, and
// let 0.054 points go.
TEST(CoverageSafeBars, ASpiralSweptAcrossItsCorridorsKeepsItsRim) {
  expectBarsKept(testing::MapFamily::kSpiral, 13);
}

}  // namespace
}  // namespace kinematic_coverage::core
