#include "trajectory_generation_tools/simulation/robot_simulator.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/simulation/path_distance.h"
#include "trajectory_generation_tools/simulation/trajectory_follower.h"

namespace kinematic_coverage::core {

RobotSimulator::RobotSimulator(const RobotModel& model) : model_(model) {
  if (!(model_.sim_time_limit / model_.sim_dt <= static_cast<double>(kMaxSteps))) {
    throw InvalidInputError("the simulated time limit " + formatNumber(model_.sim_time_limit) +
                            " s at a time step of " + formatNumber(model_.sim_dt) +
                            " s is more than the limit of " + std::to_string(kMaxSteps) +
                            " simulation steps");
  }
}

namespace {

/// A recorded step of `follower` with its errors against `desired_path`.
SimulationStep recordedStep(const TrajectoryFollower& follower, const PathDistance& desired_path) {
  const RobotState& state = follower.state();
  const Point2 position = state.pose.position();
  const Point2 offset = position - desired_path.nearestPoint(position);
  SimulationStep step;
  step.t = state.t;
  step.pose = state.pose;
  step.tracking_error_m = offset.norm();
  step.tracking_error_x_m = offset.x();
  step.tracking_error_y_m = offset.y();
  const std::vector<Pose2>& targets = follower.targets();
  const std::size_t target = std::min(follower.nextTarget(), targets.size() - 1);
  const Point2 piece_end = targets[target].position();
  const Point2 piece_start = target == 0 ? piece_end : targets[target - 1].position();
  step.target_error_m = distanceToSegment(position, piece_start, piece_end);
  if (const TimedReference* reference = follower.reference()) {
    step.time_matched_error_m = (position - reference->at(state.t).position).norm();
  }
  return step;
}

/// The indices of the steps nearest to t = k / kErrorSampleRate, k >= 1, up to the last.
std::vector<std::size_t> sampledSteps(const std::vector<SimulationStep>& steps, double sim_dt) {
  std::vector<std::size_t> indices;
  const double last_t = steps.back().t;
  for (int k = 1; k / kErrorSampleRate <= last_t + 0.5 * sim_dt; ++k) {
    const double index = std::round(k / kErrorSampleRate / sim_dt);
    indices.push_back(std::min(static_cast<std::size_t>(index), steps.size() - 1));
  }
  return indices;
}

/// Statistics of `error` over `steps`: every step but the start, or those of `indices`.
TrackingErrorStatistics statisticsOf(const std::vector<SimulationStep>& steps,
                                     double SimulationStep::*error,
                                     const std::vector<std::size_t>* indices = nullptr) {
  std::vector<double> errors;
  if (indices) {
    for (const std::size_t i : *indices) errors.push_back(steps[i].*error);
  } else {
    for (std::size_t i = 1; i < steps.size(); ++i) errors.push_back(steps[i].*error);
  }
  return summarizeTrackingErrors(std::move(errors));
}

/// The axis statistics of `steps` without the first (the start).
AxisErrorStatistics axisStatistics(const std::vector<SimulationStep>& steps) {
  AxisErrorStatistics axes;
  if (steps.size() < 2) return axes;
  for (std::size_t i = 1; i < steps.size(); ++i) {
    const double x = std::abs(steps[i].tracking_error_x_m);
    const double y = std::abs(steps[i].tracking_error_y_m);
    axes.x_mean_m += x;
    axes.y_mean_m += y;
    axes.x_max_m = std::max(axes.x_max_m, x);
    axes.y_max_m = std::max(axes.y_max_m, y);
  }
  axes.x_mean_m /= static_cast<double>(steps.size() - 1);
  axes.y_mean_m /= static_cast<double>(steps.size() - 1);
  return axes;
}

}  // namespace

SimulationResult RobotSimulator::simulate(const std::vector<Pose2>& trajectory,
                                          const std::vector<double>& times) const {
  if (trajectory.empty()) throw InvalidInputError("simulate: the trajectory has no poses");
  RobotState start;
  start.pose = trajectory.front();
  TrajectoryFollower follower(model_, trajectory, start, times);
  std::vector<Point2> path;
  path.reserve(trajectory.size());
  for (const Pose2& pose : trajectory) path.push_back(pose.position());
  const PathDistance desired_path(path);

  SimulationResult result;
  result.steps.push_back(recordedStep(follower, desired_path));
  const std::size_t step_limit =
      static_cast<std::size_t>(std::floor(model_.sim_time_limit / model_.sim_dt));
  while (!follower.finished()) {
    if (result.steps.size() > step_limit) {
      throw InvalidInputError(
          "simulate: the robot did not reach the last pose within sim_time_limit = " +
          formatNumber(model_.sim_time_limit) + " s (it was driving to pose " +
          std::to_string(follower.nextTarget() + 1) + " of " + std::to_string(trajectory.size()) +
          ")");
    }
    follower.step();
    result.steps.push_back(recordedStep(follower, desired_path));
  }
  result.traversal_time_s = follower.state().t;
  const std::vector<SimulationStep>& steps = result.steps;
  result.tracking = statisticsOf(steps, &SimulationStep::tracking_error_m);
  result.tracking_axes = axisStatistics(steps);
  result.target_tracking = statisticsOf(steps, &SimulationStep::target_error_m);
  const std::vector<std::size_t> sampled = sampledSteps(steps, model_.sim_dt);
  result.sampled_tracking = statisticsOf(steps, &SimulationStep::tracking_error_m, &sampled);
  result.sampled_target_tracking = statisticsOf(steps, &SimulationStep::target_error_m, &sampled);
  result.reference_excess = follower.referenceExcess();
  if (follower.reference()) {
    result.time_matched_tracking = statisticsOf(steps, &SimulationStep::time_matched_error_m);
    result.sampled_time_matched_tracking =
        statisticsOf(steps, &SimulationStep::time_matched_error_m, &sampled);
  }
  return result;
}

}  // namespace kinematic_coverage::core
