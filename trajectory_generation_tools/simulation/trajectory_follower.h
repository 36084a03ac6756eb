#pragma once

#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/robot_model.h"

namespace kinematic_coverage::core {

/// Where a simulated robot is and how fast it moves.
struct RobotState {
  double t = 0.0;      ///< s since the simulation started
  Pose2 pose;          ///< position and heading (yaw in (-pi, pi])
  double speed = 0.0;  ///< m/s through the water along the heading, >= 0
};

/// A planar robot that follows a trajectory's poses as a sequence of targets, as the
/// thesis's robot did in the lake (Chapter 4): it is handed one pose after the other, not
/// a timetable, so its traversal time comes out of its dynamics and controllers.
///
/// Model (one step of `sim_dt`, explicit Euler, heading updated before position):
/// - Targets. A pose at the same position as the pose before it (an in-place rotation of
///   the trajectory) is a heading target: reached when the heading is within
///   `yaw_tolerance` of its yaw. Any other pose is a position target: reached within
///   `position_tolerance` of it, or once passed (the robot lies ahead of the line through
///   the pose across its yaw), so that a robot carried off a pose does not turn back for it.
///   Reached targets are skipped in order, several in one step if need be.
/// - Position controller. Towards a position target it asks for a velocity over ground of
///   position_gain times the distance to the target, limited to v_max, along the bearing
///   to the target (a set-point controller: the robot slows towards every pose it is
///   handed). The robot measures its velocity over ground, so it steers the velocity
///   through the water that gives it in the current (crabbing); that velocity's direction
///   is the desired heading and its length the speed command. For a heading target the
///   desired heading is the target's yaw and the speed command 0 (turn in place, drifting
///   with the current).
/// - Yaw controller. With e the error to the desired heading, the yaw rate is
///   yaw_gain * e, limited to +-yaw_rate_max.
/// - Shared thrust. Turning takes thrust from surge: the speed command is at most
///   v_max * (1 - |yaw rate| / yaw_rate_max), so the robot turns in place when the heading
///   error is large instead of circling a target.
/// - Surge dynamics. The speed moves towards its command by at most a_max * sim_dt.
/// - Current. The robot moves with speed * (cos yaw, sin yaw) + (current_x, current_y).
/// The two thesis trends come out of it (docs/EXPERIMENTS.md): with a high yaw_gain the
/// turns in place are fast (the yaw rate saturates) while densely sampled arcs cost a slow
/// down at every pose, and stopping at the corners overshoots them (the robot cannot brake
/// harder than a_max); with a low yaw_gain each rotation pose is approached exponentially,
/// so finely sampled rotations (small rotation_sampling_angle) are slow.
class TrajectoryFollower {
 public:
  /// Follows `targets` from `start` with the robot `model` (its ranges checked where it
  /// was made: robotModelOf). Targets already reached at the start are skipped. Throws
  /// InvalidInputError for no targets, a non-finite target or start, or a negative start
  /// speed.
  TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets, const RobotState& start);

  /// Advances the robot by sim_dt; does nothing once finished().
  void step();

  /// True when the last target has been reached.
  bool finished() const { return next_target_ == targets_.size(); }

  const RobotState& state() const { return state_; }

  /// Index of the target the robot drives to; targets().size() once finished.
  std::size_t nextTarget() const { return next_target_; }

  const std::vector<Pose2>& targets() const { return targets_; }

 private:
  bool reached(std::size_t index) const;
  void skipReachedTargets();

  RobotModel model_;
  std::vector<Pose2> targets_;
  /// Per target: true for a heading target (same position as the target before it).
  std::vector<bool> heading_target_;
  RobotState state_;
  double start_time_ = 0.0;  ///< state_.t at the start: t = start + steps * sim_dt
  std::size_t steps_ = 0;
  std::size_t next_target_ = 0;
};

}  // namespace kinematic_coverage::core
