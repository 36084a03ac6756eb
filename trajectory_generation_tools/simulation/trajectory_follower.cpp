#include "trajectory_generation_tools/simulation/trajectory_follower.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Poses closer than this share a position: the poses of an in-place rotation.
constexpr double kSamePositionTolerance = 1e-9;

bool isFinite(const Pose2& pose) {
  return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw);
}

}  // namespace

TrajectoryFollower::TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets,
                                       const RobotState& start)
    : model_(model), targets_(std::move(targets)), state_(start) {
  if (targets_.empty()) throw InvalidInputError("trajectory follower: no poses to follow");
  heading_target_.resize(targets_.size(), false);
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    if (!isFinite(targets_[i])) {
      throw InvalidInputError("trajectory follower: pose " + std::to_string(i) + " is not finite");
    }
    heading_target_[i] = i > 0 && (targets_[i].position() - targets_[i - 1].position()).norm() <=
                                      kSamePositionTolerance;
  }
  if (!isFinite(state_.pose) || !std::isfinite(state_.t) || !std::isfinite(state_.speed) ||
      state_.speed < 0.0) {
    throw InvalidInputError(
        "trajectory follower: the start state must be finite with a speed >= 0");
  }
  state_.pose.yaw = wrapAngle(state_.pose.yaw);
  start_time_ = state_.t;
  skipReachedTargets();
}

bool TrajectoryFollower::reached(std::size_t index) const {
  const Pose2& target = targets_[index];
  if (heading_target_[index]) {
    return std::abs(wrapAngle(target.yaw - state_.pose.yaw)) <= model_.yaw_tolerance;
  }
  const Point2 offset = state_.pose.position() - target.position();
  const Point2 along(std::cos(target.yaw), std::sin(target.yaw));
  return offset.norm() <= model_.position_tolerance || offset.dot(along) >= 0.0;
}

void TrajectoryFollower::skipReachedTargets() {
  while (next_target_ < targets_.size() && reached(next_target_)) ++next_target_;
}

void TrajectoryFollower::step() {
  if (finished()) return;
  const RobotModel& p = model_;
  const VehicleLimits& limits = model_.vehicle;
  const Pose2& target = targets_[next_target_];
  const Point2 current(p.current_x, p.current_y);
  double heading_error = 0.0;
  double speed_command = 0.0;
  if (heading_target_[next_target_]) {
    heading_error = wrapAngle(target.yaw - state_.pose.yaw);
  } else {
    // The velocity over ground the position controller asks for, and the velocity through
    // the water that gives it in the current.
    const Point2 to_target = target.position() - state_.pose.position();
    const Point2 over_ground =
        std::min(limits.v_max, p.position_gain * to_target.norm()) * to_target.normalized();
    const Point2 through_water = over_ground - current;
    heading_error = wrapAngle(std::atan2(through_water.y(), through_water.x()) - state_.pose.yaw);
    speed_command = std::min(limits.v_max, through_water.norm());
  }
  const double yaw_rate =
      std::clamp(p.yaw_gain * heading_error, -limits.yaw_rate_max, limits.yaw_rate_max);
  speed_command =
      std::min(speed_command, limits.v_max * (1.0 - std::abs(yaw_rate) / limits.yaw_rate_max));
  const double speed_change = limits.a_max * p.sim_dt;
  state_.speed += std::clamp(speed_command - state_.speed, -speed_change, speed_change);
  state_.speed = std::max(state_.speed, 0.0);
  state_.pose.yaw = wrapAngle(state_.pose.yaw + yaw_rate * p.sim_dt);
  const Point2 velocity =
      state_.speed * Point2(std::cos(state_.pose.yaw), std::sin(state_.pose.yaw)) + current;
  state_.pose.x += velocity.x() * p.sim_dt;
  state_.pose.y += velocity.y() * p.sim_dt;
  ++steps_;
  state_.t = start_time_ + static_cast<double>(steps_) * p.sim_dt;
  skipReachedTargets();
}

}  // namespace kinematic_coverage::core
