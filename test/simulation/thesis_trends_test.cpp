// The thesis's two experiments (Chapter 4, Tables 4.1 to 4.3) in simulation: the lake
// missions planned smoothed and unsmoothed, each followed by the same robot, the default
// dynamic vehicle (config/default.yaml), in the lake's disturbances or in calm water with
// exact navigation; the vehicle's and the lake's values were chosen before these
// experiments ran. docs/EXPERIMENTS.md reports which of the thesis's trends appear.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/stage_options.h"
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
  run.coverage_percent =
      measureTrajectoryCoverage(planned.free_area, planned.plan.exact_offset_parts,
                                mission.parameters, actual)
          .report.coverage_percent;
  return run;
}

/// The lake of docs/EXPERIMENTS.md: a current fluctuating by 0.02 m/s per axis and a
/// navigation error of 0.1 m per axis (set before the experiments ran with them).
const std::vector<std::string> kLake{"current_sigma=0.02", "navigation_sigma=0.1"};

/// Experiment 2's robot: a lower yaw gain and finer rotations, the thesis's two changes.
const std::vector<std::string> kLowGain{"yaw_gain=2", "rotation_sampling_angle=0.1"};

/// `first` followed by `second`.
std::vector<std::string> operator+(std::vector<std::string> first,
                                   const std::vector<std::string>& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

/// The overrides with `smoothing` on or off, smoothing by the thesis's Algorithm 1 (the
/// global smoothing strategy makes the smoothed runs faster than the thesis's).
std::vector<std::string> with(std::vector<std::string> overrides, const std::string& smoothing) {
  overrides.push_back("smoothing=" + smoothing);
  overrides.push_back("smoothing_strategy=local");
  return overrides;
}

/// Table 4.2's percentiles (1st to 99th) of the error, metres.
const std::vector<double> kThesisSmoothedPercentiles{0.01, 0.02, 0.03, 0.05, 0.08,
                                                     0.13, 0.21, 0.28, 0.54};
const std::vector<double> kThesisUnsmoothedPercentiles{0.01, 0.03, 0.04, 0.07, 0.13,
                                                       0.23, 0.34, 0.47, 0.63};

/// Expects the 50th to the 99th percentile of `run` within a factor of 3 of `thesis`'s.
void expectPercentilesNear(const RobotRun& run, const std::vector<double>& thesis,
                           const std::string& label) {
  for (std::size_t i = 0; i < kTrackingErrorPercentiles.size(); ++i) {
    if (kTrackingErrorPercentiles[i] < 50) continue;
    const double ours = run.simulation.tracking.percentiles_m[i];
    EXPECT_GE(ours, thesis[i] / 3.0) << label << " " << kTrackingErrorPercentiles[i];
    EXPECT_LE(ours, thesis[i] * 3.0) << label << " " << kTrackingErrorPercentiles[i];
  }
}

TEST(ThesisTrendsTest, HighYawGainOnLake30TurnsInPlaceFasterWithTheLakesErrors) {
  // Tables 4.1 and 4.2, in the lake: unsmoothed 1241 s against smoothed 1529 s, and the
  // error percentiles from the median up within a factor of 3 of Table 4.2's for both.
  // Table 4.1's other half, the smoothed trajectory tracked 35 % better, does not appear
  // with this vehicle in the lake or in calm water (docs/EXPERIMENTS.md).
  const RobotRun smoothed = planAndSimulate("lake_30x30", with(kLake, "true"));
  const RobotRun unsmoothed = planAndSimulate("lake_30x30", with(kLake, "false"));
  EXPECT_LT(unsmoothed.simulation.traversal_time_s, smoothed.simulation.traversal_time_s);
  expectPercentilesNear(smoothed, kThesisSmoothedPercentiles, "smoothed");
  expectPercentilesNear(unsmoothed, kThesisUnsmoothedPercentiles, "unsmoothed");
  // As in Table 4.1, neither loses coverage worth speaking of.
  EXPECT_GT(smoothed.coverage_percent, 99.9);
  EXPECT_GT(unsmoothed.coverage_percent, 99.9);
}

TEST(ThesisTrendsTest, LowYawGainAndFineRotationsOnLake7MakeSmoothingFaster) {
  // Table 4.3: with a lower yaw gain and more rotation poses, smoothed 531 s against
  // unsmoothed 703 s, in the lake and in calm water with exact navigation.
  const RobotRun smoothed = planAndSimulate("lake_7_5", with(kLowGain + kLake, "true"));
  const RobotRun unsmoothed = planAndSimulate("lake_7_5", with(kLowGain + kLake, "false"));
  EXPECT_LT(smoothed.simulation.traversal_time_s, unsmoothed.simulation.traversal_time_s);
  // The reversal comes from the robot, not from the map: with the first experiment's high
  // gain and coarse rotations, turning in place is faster on this map too.
  const RobotRun smoothed_high_gain = planAndSimulate("lake_7_5", with(kLake, "true"));
  const RobotRun unsmoothed_high_gain = planAndSimulate("lake_7_5", with(kLake, "false"));
  EXPECT_LT(unsmoothed_high_gain.simulation.traversal_time_s,
            smoothed_high_gain.simulation.traversal_time_s);
}

TEST(ThesisTrendsTest, InCalmWaterLake7SmoothedIsFasterButTracksWorse) {
  // Table 4.3 whole (smoothed 531 s and 284 m against unsmoothed 703 s and 239 m) appears
  // in calm water with exact navigation: the unsmoothed robot stops and turns on the
  // path, the smoothed one lags on the tight arcs with the low yaw gain. In the lake the
  // current and navigation error push the slowly turning unsmoothed robot off its
  // corners and the order of the errors turns (docs/EXPERIMENTS.md).
  const RobotRun smoothed = planAndSimulate("lake_7_5", with(kLowGain, "true"));
  const RobotRun unsmoothed = planAndSimulate("lake_7_5", with(kLowGain, "false"));
  EXPECT_LT(smoothed.simulation.traversal_time_s, unsmoothed.simulation.traversal_time_s);
  EXPECT_GT(smoothed.simulation.tracking.sum_m, unsmoothed.simulation.tracking.sum_m);
}

TEST(ThesisTrendsTest, ContinuousCurvatureTurnsTrackBetterThanArcsInCalmWater) {
  // Beyond the thesis: in calm water with exact navigation, clothoid transitions track
  // experiment 1's trajectory better than the same strategy's arcs (no curvature jump to
  // lag behind). They do not track better than the unsmoothed trajectory, which stops on
  // its corners. In experiment 2, whose turns keep the 0.4 m wall distance, the two
  // curves track alike; docs/EXPERIMENTS.md reports both.
  const std::vector<std::string> arcs{"smoothing=true"};
  const std::vector<std::string> clothoids{"smoothing=true", "turn_curve=clothoid"};
  EXPECT_LT(planAndSimulate("lake_30x30", clothoids).simulation.tracking.sum_m,
            planAndSimulate("lake_30x30", arcs).simulation.tracking.sum_m);
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
