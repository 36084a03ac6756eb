// With the timed controller (the default), the vectored vehicle drives the planner's
// trajectories of the shipped missions in about the planned time and on the planned
// reference, in calm water with exact navigation, smoothed and unsmoothed: within 5 % of
// the planned traversal_time_s, and the time-matched error |p(t) - p_d(t)| under 0.2 m at
// the 95th percentile. (Which trajectory is faster or tracked better is not asserted.)

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/stage_options.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"
#include "trajectory_generation_tools/simulation/timed_reference.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {
namespace {

/// Share of the planned time by which the driven time may differ.
constexpr double kTimeShare = 0.05;
/// m: the bound of the time-matched error's 95th percentile.
constexpr double kTimeMatchedErrorP95 = 0.2;

TEST(TimedTracking, DrivesTheShippedMissionsInThePlannedTimeOnTheReference) {
  for (const char* name : {"lake_30x30", "lake_7_5", "parallelogram_60"}) {
    for (const char* smoothing : {"smoothing=true", "smoothing=false"}) {
      SCOPED_TRACE(std::string(name) + " " + smoothing);
      const Mission mission = MissionFileReader().read(
          std::string(KC_SOURCE_DIR) + "/config/missions/" + name + ".yaml", {smoothing});
      const PlannedMission planned = planMission(mission);
      const GeneratedTrajectory trajectory =
          TrajectoryGenerator(trajectoryOptionsOf(mission.parameters))
              .generate(planned.plan.waypoints, planned.free_area);
      std::vector<Pose2> poses;
      std::vector<double> times;
      for (const TrajectoryPose& pose : trajectory.poses) {
        poses.push_back(pose.pose());
        times.push_back(pose.t);
      }
      const RobotModel robot = robotModelOf(mission.parameters);
      ASSERT_EQ(robot.controller, TrackingController::kTimed);
      ASSERT_EQ(robot.disturbance.navigation_sigma, 0.0);
      const SimulationResult result = RobotSimulator(robot).simulate(poses, times);
      EXPECT_NEAR(result.traversal_time_s, trajectory.traversal_time_s,
                  kTimeShare * trajectory.traversal_time_s);
      const TimedReference reference(poses, times);
      std::vector<double> errors;
      for (const SimulationStep& step : result.steps) {
        errors.push_back((step.pose.position() - reference.at(step.t).position).norm());
      }
      std::sort(errors.begin(), errors.end());
      EXPECT_LT(errors[errors.size() * 95 / 100], kTimeMatchedErrorP95);
    }
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
