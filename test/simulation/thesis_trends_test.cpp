// The thesis's two experiments (Chapter 4, Tables 4.1 to 4.3) in simulation: the lake
// missions planned smoothed and unsmoothed, each followed by the same robot, the default
// dynamic vehicle (config/default.yaml, its values chosen before these experiments ran).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/mission/mission_planner.h"
#include "polygon_coverage_ros_bridge/mission/trajectory_coverage.h"
#include "polygon_coverage_ros_bridge/parameters/stage_options.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {
namespace {

/// One robot run on a planned mission and the coverage of its actual poses.
struct RobotRun {
  SimulationResult simulation;
  double coverage_percent = 0.0;
};

/// Plans `mission_name` (config/missions) with `overrides`, generates its trajectory and
/// simulates the robot of the same parameters on it.
RobotRun planAndSimulate(const std::string& mission_name,
                         const std::vector<std::string>& overrides) {
  const Mission mission = MissionFileReader().read(
      std::string(KC_SOURCE_DIR) + "/config/missions/" + mission_name + ".yaml", overrides);
  const PlannedMission planned = planMission(mission);
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(trajectoryOptionsOf(mission.parameters))
          .generate(planned.plan.waypoints, planned.free_area);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
  RobotRun run;
  run.simulation = RobotSimulator(robotModelOf(mission.parameters)).simulate(poses);
  std::vector<Pose2> actual;
  for (const SimulationStep& step : run.simulation.steps) actual.push_back(step.pose);
  run.coverage_percent = measureTrajectoryCoverage(planned.free_area, planned.plan.offset_parts,
                                                   mission.parameters, actual)
                             .report.coverage_percent;
  return run;
}

/// The overrides with `smoothing` on or off, smoothing by the thesis's Algorithm 1 (the
/// global smoothing strategy makes the smoothed runs faster than the thesis's).
std::vector<std::string> with(std::vector<std::string> overrides, const std::string& smoothing) {
  overrides.push_back("smoothing=" + smoothing);
  overrides.push_back("smoothing_strategy=local");
  return overrides;
}

TEST(ThesisTrendsTest, HighYawGainOnLake30TurnsInPlaceFasterButTracksWorse) {
  // Tables 4.1 and 4.2: unsmoothed 1241 s against smoothed 1529 s, but 452 m against 293 m
  // of cumulative error (35 % less when smoothed), and the 99th percentile of the error
  // lower when smoothed. The robot: config/default.yaml (yaw_gain 5,
  // rotation_sampling_angle 0.2).
  const RobotRun smoothed = planAndSimulate("lake_30x30", with({}, "true"));
  const RobotRun unsmoothed = planAndSimulate("lake_30x30", with({}, "false"));
  const TrackingErrorStatistics& s = smoothed.simulation.tracking;
  const TrackingErrorStatistics& u = unsmoothed.simulation.tracking;
  EXPECT_LT(unsmoothed.simulation.traversal_time_s, smoothed.simulation.traversal_time_s);
  EXPECT_LE(s.sum_m, 0.75 * u.sum_m);
  EXPECT_LT(s.mean_m, u.mean_m);
  EXPECT_LT(s.percentiles_m.back(), u.percentiles_m.back());
  // As in Table 4.1, neither loses coverage worth speaking of.
  EXPECT_GT(smoothed.coverage_percent, 99.9);
  EXPECT_GT(unsmoothed.coverage_percent, 99.9);
}

TEST(ThesisTrendsTest, LowYawGainAndFineRotationsOnLake7MakeSmoothingFaster) {
  // Table 4.3: with a lower yaw gain and more rotation poses, smoothed 531 s against
  // unsmoothed 703 s.
  const std::vector<std::string> robot{"yaw_gain=2", "rotation_sampling_angle=0.1"};
  const RobotRun smoothed = planAndSimulate("lake_7_5", with(robot, "true"));
  const RobotRun unsmoothed = planAndSimulate("lake_7_5", with(robot, "false"));
  EXPECT_LT(smoothed.simulation.traversal_time_s, unsmoothed.simulation.traversal_time_s);
  // Table 4.3's other half, smoothed tracking worse (284 m against 239 m), does not appear
  // with this vehicle: the unsmoothed robot coasts past every corner and turns slowly
  // there, off the path (docs/EXPERIMENTS.md).
  // The reversal comes from the robot, not from the map: with the first experiment's high
  // gain and coarse rotations, turning in place is faster on this map too.
  const RobotRun smoothed_high_gain = planAndSimulate("lake_7_5", with({}, "true"));
  const RobotRun unsmoothed_high_gain = planAndSimulate("lake_7_5", with({}, "false"));
  EXPECT_LT(unsmoothed_high_gain.simulation.traversal_time_s,
            smoothed_high_gain.simulation.traversal_time_s);
}

TEST(ThesisTrendsTest, ContinuousCurvatureTurnsTrackBetterInBothExperiments) {
  // Beyond the thesis: with clothoid transitions (the default strategy), the smoothed
  // trajectory tracks better than the unsmoothed one in both experiments, with no
  // reversal, and stays the faster one in experiment 2.
  const std::vector<std::string> clothoid{"smoothing=true", "turn_curve=clothoid"};
  const RobotRun lake30 = planAndSimulate("lake_30x30", clothoid);
  const RobotRun lake30_unsmoothed = planAndSimulate("lake_30x30", {"smoothing=false"});
  EXPECT_LT(lake30.simulation.tracking.sum_m, lake30_unsmoothed.simulation.tracking.sum_m);
  std::vector<std::string> low_gain{"yaw_gain=2", "rotation_sampling_angle=0.1"};
  std::vector<std::string> lake7_clothoid = low_gain;
  lake7_clothoid.insert(lake7_clothoid.end(), clothoid.begin(), clothoid.end());
  low_gain.push_back("smoothing=false");
  const RobotRun lake7 = planAndSimulate("lake_7_5", lake7_clothoid);
  const RobotRun lake7_unsmoothed = planAndSimulate("lake_7_5", low_gain);
  EXPECT_LT(lake7.simulation.tracking.sum_m, lake7_unsmoothed.simulation.tracking.sum_m);
  EXPECT_LT(lake7.simulation.traversal_time_s, lake7_unsmoothed.simulation.traversal_time_s);
}

TEST(ThesisTrendsTest, ACurrentGrowsTheTrackingErrorAndCostsCoverage) {
  // The thesis's outlook: stronger currents. The robot crabs and drifts off its sweeps.
  const RobotRun calm = planAndSimulate("lake_30x30", with({}, "true"));
  const RobotRun current =
      planAndSimulate("lake_30x30", with({"current_x=0.2", "current_y=0.1"}, "true"));
  EXPECT_GT(current.simulation.tracking.mean_m, 5.0 * calm.simulation.tracking.mean_m);
  EXPECT_GT(current.simulation.tracking.percentiles_m.back(),
            calm.simulation.tracking.percentiles_m.back());
  EXPECT_LT(current.coverage_percent, calm.coverage_percent - 1.0);
}

}  // namespace
}  // namespace kinematic_coverage::core
