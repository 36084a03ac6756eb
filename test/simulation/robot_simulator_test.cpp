#include "trajectory_generation_tools/simulation/robot_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"
#include "trajectory_generation_tools/simulation/timed_reference.h"

namespace kinematic_coverage::core {
namespace {

/// An L: 6 m along x, a quarter turn in place, 4 m along y, a pose every 0.5 m.
std::vector<Pose2> lPath() {
  std::vector<Pose2> poses;
  for (int i = 0; i <= 12; ++i) poses.push_back({0.5 * i, 0.0, 0.0});
  for (int i = 1; i <= 4; ++i) poses.push_back({6.0, 0.0, M_PI / 8 * i});
  for (int i = 1; i <= 8; ++i) poses.push_back({6.0, 0.5 * i, M_PI / 2});
  return poses;
}

RobotModel modelWith(const std::string& controller, const std::string& vehicle, double sim_dt) {
  PlannerParameters parameters;
  parameters.controller = controller;
  parameters.vehicle_model = vehicle;
  parameters.sim_dt = sim_dt;
  return robotModelOf(parameters);
}

TEST(RobotSimulatorTest, SamplesItsErrorsAtTwoHertz) {
  // The sampled statistics take the steps at t = 0.5 s, 1 s, ...: as many as whole half
  // seconds in the run, whatever sim_dt, each the step's own error.
  const std::vector<Pose2> poses = lPath();
  for (const double sim_dt : {0.1, 0.05, 0.02}) {
    const RobotModel model = modelWith("timed", "dynamic", sim_dt);
    const SimulationResult result =
        RobotSimulator(model).simulate(poses, PoseSequenceTiming(model.vehicle).times(poses));
    const double duration = result.traversal_time_s;
    const std::size_t samples =
        static_cast<std::size_t>(std::floor(duration * kErrorSampleRate + 1e-9));
    ASSERT_GT(samples, 10u);
    double sum = 0.0;
    double target_sum = 0.0;
    double time_matched_sum = 0.0;
    for (std::size_t k = 1; k <= samples; ++k) {
      const SimulationStep& step =
          result.steps[static_cast<std::size_t>(std::round(k / kErrorSampleRate / sim_dt))];
      EXPECT_NEAR(step.t, k / kErrorSampleRate, 1e-9) << sim_dt;
      sum += step.tracking_error_m;
      target_sum += step.target_error_m;
      time_matched_sum += step.time_matched_error_m;
    }
    EXPECT_NEAR(result.sampled_tracking.sum_m, sum, 1e-12) << sim_dt;
    EXPECT_NEAR(result.sampled_tracking.mean_m, sum / samples, 1e-12) << sim_dt;
    EXPECT_NEAR(result.sampled_target_tracking.sum_m, target_sum, 1e-12) << sim_dt;
    ASSERT_TRUE(result.sampled_time_matched_tracking) << sim_dt;
    EXPECT_NEAR(result.sampled_time_matched_tracking->sum_m, time_matched_sum, 1e-12) << sim_dt;
  }
}

TEST(RobotSimulatorTest, TheTimeMatchedErrorIsTheDistanceToTheTrackedReference) {
  // For timed, to the trajectory's own times; for pose_stream, to pose i at i / pose_rate;
  // the controllers that track no reference report none.
  const std::vector<Pose2> poses = lPath();
  for (const std::string& controller : {"timed", "pose_stream", "setpoint", "los"}) {
    const RobotModel model = modelWith(controller, "dynamic", 0.1);
    const std::vector<double> times = PoseSequenceTiming(model.vehicle).times(poses);
    const SimulationResult result = RobotSimulator(model).simulate(poses, times);
    const bool tracks_reference = controller == "timed" || controller == "pose_stream";
    EXPECT_EQ(result.time_matched_tracking.has_value(), tracks_reference) << controller;
    EXPECT_EQ(result.sampled_time_matched_tracking.has_value(), tracks_reference) << controller;
    if (!tracks_reference) {
      for (const SimulationStep& step : result.steps) EXPECT_EQ(step.time_matched_error_m, 0.0);
      continue;
    }
    std::vector<double> reference_times = times;
    if (controller == "pose_stream") {
      for (std::size_t i = 0; i < poses.size(); ++i) reference_times[i] = i / model.pose_rate;
    }
    const TimedReference reference(poses, reference_times);
    double sum = 0.0;
    for (std::size_t i = 1; i < result.steps.size(); ++i) {
      const SimulationStep& step = result.steps[i];
      const double expected = (step.pose.position() - reference.at(step.t).position).norm();
      EXPECT_NEAR(step.time_matched_error_m, expected, 1e-12) << controller << " " << step.t;
      sum += expected;
    }
    EXPECT_NEAR(result.time_matched_tracking->sum_m, sum, 1e-9) << controller;
  }
}

TEST(RobotSimulatorTest, SaysWhereTheReferenceAsksMoreThanTheVehicleCanDo) {
  // The planner's timing stays within the vehicle's limits; a pose stream at 1 Hz along
  // poses 1 m apart asks for 1 m/s, beyond v_max; a dynamic vehicle whose thrusters give
  // less than the drag at the planned speed cannot follow the planned times.
  std::vector<Pose2> line;
  for (int i = 0; i <= 10; ++i) line.push_back({1.0 * i, 0.0, 0.0});
  for (const std::string& vehicle : {"dynamic", "kinematic"}) {
    const RobotModel timed = modelWith("timed", vehicle, 0.1);
    const std::vector<double> times = PoseSequenceTiming(timed.vehicle).times(line);
    EXPECT_EQ(RobotSimulator(timed).simulate(line, times).reference_excess.duration_s, 0.0)
        << vehicle;
    const RobotModel stream = modelWith("pose_stream", vehicle, 0.1);
    const ReferenceExcess excess = RobotSimulator(stream).simulate(line, times).reference_excess;
    EXPECT_GT(excess.duration_s, 5.0) << vehicle;
    EXPECT_NE(excess.first_demand.find("v_max"), std::string::npos) << excess.first_demand;
    EXPECT_LT(excess.first_t, 1.0) << vehicle;
    EXPECT_EQ(excess.first_pose, 1u) << vehicle;
  }
  RobotModel weak = modelWith("timed", "dynamic", 0.1);
  weak.body.thrust_max = 0.5 * weak.body.surgeDamping(weak.vehicle.v_max);
  weak.sim_time_limit = 600.0;
  const ReferenceExcess excess = RobotSimulator(weak)
                                     .simulate(line, PoseSequenceTiming(weak.vehicle).times(line))
                                     .reference_excess;
  EXPECT_GT(excess.duration_s, 0.0);
  EXPECT_NE(excess.first_demand.find("thrust"), std::string::npos) << excess.first_demand;
}

TEST(RobotSimulatorTest, EveryControllerDrivesDegenerateTrajectoriesToTheirEnd) {
  // Valid input that is degenerate: one pose, a repeated pose, a reversal in place, legs far
  // shorter than the turning radius, and poses that share a time. Every controller on both
  // vehicles arrives at the last pose, within twice the position tolerance (the torpedo-like
  // timed tracker ends at or past it, and los and setpoint count a passed pose as reached).
  std::vector<Pose2> reversal;
  for (int i = 0; i <= 4; ++i) reversal.push_back({0.5 * i, 0.0, 0.0});
  for (int i = 1; i <= 8; ++i) reversal.push_back({2.0, 0.0, M_PI / 8 * i});
  for (int i = 1; i <= 4; ++i) reversal.push_back({2.0 - 0.5 * i, 0.0, M_PI});
  std::vector<Pose2> zigzag;
  for (int i = 0; i <= 20; ++i) zigzag.push_back({0.1 * i, 0.05 * (i % 2), 0.0});
  const std::vector<std::pair<std::string, std::vector<Pose2>>> trajectories{
      {"one pose", {{1.0, 2.0, 0.5}}},
      {"a repeated pose", {{1.0, 2.0, 0.5}, {1.0, 2.0, 0.5}, {3.0, 2.0, 0.0}, {3.0, 2.0, 0.0}}},
      {"a reversal in place", reversal},
      {"short legs", zigzag}};
  for (const auto& [name, poses] : trajectories) {
    for (const std::string& controller : {"timed", "pose_stream", "setpoint", "los"}) {
      for (const std::string& vehicle : {"dynamic", "kinematic"}) {
        SCOPED_TRACE(name + ", " + controller + ", " + vehicle);
        RobotModel model = modelWith(controller, vehicle, 0.1);
        model.sim_time_limit = 600.0;
        std::vector<double> times = PoseSequenceTiming(model.vehicle).times(poses);
        if (name == "a repeated pose") times = {0.0, 0.0, 5.0, 5.0};
        const SimulationResult result = RobotSimulator(model).simulate(poses, times);
        EXPECT_LT((result.steps.back().pose.position() - poses.back().position()).norm(),
                  2.0 * model.position_tolerance);
        for (const SimulationStep& step : result.steps) {
          ASSERT_TRUE(std::isfinite(step.pose.x) && std::isfinite(step.pose.y) &&
                      std::isfinite(step.pose.yaw));
        }
      }
    }
  }
}

TEST(RobotSimulatorTest, TheSameSeedGivesTheSameRunForEveryController) {
  const std::vector<Pose2> poses = lPath();
  for (const std::string& controller : {"timed", "pose_stream", "setpoint", "los"}) {
    RobotModel model = modelWith(controller, "dynamic", 0.1);
    model.disturbance.current_sigma = 0.02;
    model.disturbance.navigation_sigma = 0.1;
    model.disturbance.seed = 7;
    const std::vector<double> times = PoseSequenceTiming(model.vehicle).times(poses);
    const SimulationResult first = RobotSimulator(model).simulate(poses, times);
    const SimulationResult second = RobotSimulator(model).simulate(poses, times);
    ASSERT_EQ(first.steps.size(), second.steps.size()) << controller;
    for (std::size_t i = 0; i < first.steps.size(); ++i) {
      EXPECT_EQ(first.steps[i].pose.x, second.steps[i].pose.x) << controller << " " << i;
      EXPECT_EQ(first.steps[i].pose.y, second.steps[i].pose.y) << controller << " " << i;
      EXPECT_EQ(first.steps[i].pose.yaw, second.steps[i].pose.yaw) << controller << " " << i;
    }
    model.disturbance.seed = 8;
    const SimulationResult other = RobotSimulator(model).simulate(poses, times);
    EXPECT_NE(other.tracking.sum_m, first.tracking.sum_m) << controller;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
