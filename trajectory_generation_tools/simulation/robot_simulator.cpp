#include "trajectory_generation_tools/simulation/robot_simulator.h"

#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/simulation/path_distance.h"
#include "trajectory_generation_tools/simulation/trajectory_follower.h"

namespace kinematic_coverage::core {

RobotSimulator::RobotSimulator(const RobotModel& model) : model_(model) {
  if (!(model_.sim_time_limit / model_.sim_dt <= static_cast<double>(kMaxSteps))) {
    throw InvalidInputError("sim_time_limit = " + formatNumber(model_.sim_time_limit) +
                            " s with sim_dt = " + formatNumber(model_.sim_dt) +
                            " s is more than the limit of " + std::to_string(kMaxSteps) +
                            " simulation steps");
  }
}

SimulationResult RobotSimulator::simulate(const std::vector<Pose2>& trajectory) const {
  if (trajectory.empty()) throw InvalidInputError("simulate: the trajectory has no poses");
  RobotState start;
  start.pose = trajectory.front();
  TrajectoryFollower follower(model_, trajectory, start);
  std::vector<Point2> path;
  path.reserve(trajectory.size());
  for (const Pose2& pose : trajectory) path.push_back(pose.position());
  const PathDistance desired_path(path);

  SimulationResult result;
  result.steps.push_back(
      {0.0, follower.state().pose, desired_path.distance(start.pose.position())});
  std::vector<double> errors;
  const std::size_t step_limit =
      static_cast<std::size_t>(std::floor(model_.sim_time_limit / model_.sim_dt));
  while (!follower.finished()) {
    if (errors.size() >= step_limit) {
      throw InvalidInputError(
          "simulate: the robot did not reach the last pose within sim_time_limit = " +
          formatNumber(model_.sim_time_limit) + " s (it was driving to pose " +
          std::to_string(follower.nextTarget() + 1) + " of " + std::to_string(trajectory.size()) +
          ")");
    }
    follower.step();
    const RobotState& state = follower.state();
    const double error = desired_path.distance(state.pose.position());
    result.steps.push_back({state.t, state.pose, error});
    errors.push_back(error);
  }
  result.traversal_time_s = follower.state().t;
  result.tracking = summarizeTrackingErrors(std::move(errors));
  return result;
}

}  // namespace kinematic_coverage::core
