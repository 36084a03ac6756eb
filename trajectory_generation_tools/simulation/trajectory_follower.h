#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/environment_disturbance.h"
#include "trajectory_generation_tools/simulation/line_of_sight_guidance.h"
#include "trajectory_generation_tools/simulation/planar_rigid_body.h"
#include "trajectory_generation_tools/simulation/robot_model.h"
#include "trajectory_generation_tools/simulation/timed_reference.h"

namespace kinematic_coverage::core {

/// Where a simulated robot is and how fast it moves.
struct RobotState {
  double t = 0.0;         ///< s since the simulation started
  Pose2 pose;             ///< position and heading (yaw in (-pi, pi])
  double speed = 0.0;     ///< m/s through the water along the heading (surge)
  double sway = 0.0;      ///< m/s through the water to the left (0 for the kinematic vehicle)
  double yaw_rate = 0.0;  ///< rad/s
};

/// Where a tracked reference asked for more than the vehicle can do (controllers timed and
/// pose_stream): its own demand, before any correction of the robot's error, is beyond the
/// vehicle: a speed through the water beyond v_max, a yaw rate beyond yaw_rate_max, or, for
/// the dynamic vehicle, a feedforward (the reference's acceleration through mass and added
/// mass, the Coriolis terms and the damping at its velocity through the water) that the
/// thrusters cannot give.
struct ReferenceExcess {
  std::string first_demand;                ///< what it first asked for, and the limit it was beyond
  double duration_s = 0.0;                 ///< simulated time under such a reference; 0: never
  double first_t = 0.0;                    ///< s: when it first did
  Point2 first_position = Point2::Zero();  ///< m: where the reference was then
  std::size_t first_pose = 0;              ///< index of the pose the reference headed to then
};

/// A planar robot that tracks a trajectory. By default (controller: timed) it tracks the
/// reference p_d(t) that the poses and their times make (TimedReference): per world axis
/// the reference's acceleration plus PD on its velocity and position (Kp = M wn^2, Kd =
/// 2 zeta wn M), turned into body forces through the rigid body's model (timedForces), the
/// kinematic vehicle's speed and yaw rate from v_d + wn (p_d - p); it is done once the
/// reference has ended and the robot is at its last pose. controller: pose_stream is the
/// same tracker on the reference that passes pose i at i / pose_rate (the poses streamed at
/// a fixed rate instead of at the trajectory's times). controller: los steers the course of
/// line-of-sight guidance (LineOfSightGuidance, look-ahead los_lookahead, 0: the turning
/// radius) on the piece to the next target, its heading off that course by the measured
/// sideslip, at the reference's speed on that piece (its length over its duration), braked
/// as below and scaled by the cosine of the heading error; it turns in place at heading
/// targets, and uses the targets, yaw controller and vehicle loops of setpoint, below.
/// With controller: setpoint it
/// follows the poses as a sequence of targets, as the thesis's robot did in the lake
/// (Chapter 4): it is handed one pose after the other, not a timetable, so its traversal
/// time comes out of its dynamics and controllers, as follows.
///
/// Every step of `sim_dt`:
/// - Navigation. The robot knows its position only through its navigation solution: the
///   true position plus the navigation error of `disturbance` (0 by default). Targets and
///   controllers below see that estimate; the water moves the true body, with the current
///   (current_x, current_y) plus its fluctuation, of which the controller knows the mean.
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
///   desired heading is the target's yaw and the speed command 0 (turn in place).
/// - Braking. The velocity over ground is also at most sqrt(2 * a_max * d), with d the distance
///   along the poses to the next stop (the position target before an in-place rotation, or
///   the last target): the fastest speed from which a_max still stops the robot there, so
///   that it turns in place on the path and not past a corner, towards a wall.
/// - Yaw controller. With e the error to the desired heading, the yaw-rate command is
///   yaw_gain * e, limited to +-yaw_rate_max.
/// - Shared thrust. Turning takes thrust from surge: the speed command is at most
///   v_max * (1 - |yaw-rate command| / yaw_rate_max), so the robot turns in place when the
///   heading error is large instead of circling a target.
/// - Acceleration limit. The surge-speed reference moves towards the speed command by at
///   most a_max * sim_dt, and stays >= 0.
/// - Vehicle, `vehicle_model: kinematic`: the surge speed is the reference and the yaw rate
///   the command, at once (explicit Euler, heading before position); the robot moves with
///   speed * (cos yaw, sin yaw) + current.
/// - Vehicle, `vehicle_model: dynamic`: a PlanarRigidBody driven by two velocity loops,
///   each a proportional term on its inertia plus feedforwards of its damping (and, in
///   surge, of the reference's acceleration, so that braking is not late):
///   X = m11 * (u_ref' + surge_loop_gain * (u_ref(t0) - u)) + D_u(u_ref) and
///   N = m33 * yaw_rate_loop_gain * (r_cmd - r) + D_r(r_cmd). With sway actuated (the
///   vectored frame, the default) a third loop holds the sway speed through the water at
///   zero: Y = m11 u r - m22 * surge_loop_gain * v, the Coriolis force fed forward. The
///   thrusters give what they can of (X, Y, N) (PlanarRigidBody::limited), held over the
///   step. Without sway actuation (the torpedo-like variant) the body slips outwards in a
///   turn.
/// The thesis's time trends come out of it (docs/EXPERIMENTS.md): with a high yaw_gain the
/// turns in place are fast (the yaw rate saturates) while densely sampled arcs cost a slow
/// down at every pose; with a low yaw_gain each rotation pose is approached exponentially,
/// so finely sampled rotations (small rotation_sampling_angle) are slow. Its tracking
/// errors come from the slip and lag on arcs, the current and the navigation error.
class TrajectoryFollower {
 public:
  /// Follows `targets` from `start` with the robot `model` (its ranges checked where it
  /// was made: robotModelOf). Targets already reached at the start are skipped. Throws
  /// InvalidInputError for no targets, or a non-finite target or start.
  /// With `controller: timed` or `los`, `times` holds each target's time (the trajectory's
  /// t column): timed tracks the reference p_d(t) they make (TimedReference), los takes its
  /// speeds from them; both throw InvalidInputError without them. setpoint and pose_stream
  /// ignore them.
  TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets, const RobotState& start,
                     std::vector<double> times = {});

  /// As above, in a lake whose disturbances have already run on (`lake`, e.g. the
  /// disturbance() of the follower of the trajectory before, for a robot handed a new
  /// trajectory mid-mission) instead of the model's disturbances from their first draws.
  TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets, const RobotState& start,
                     const EnvironmentDisturbance& lake, std::vector<double> times = {});

  /// Advances the robot by sim_dt; does nothing once finished().
  void step();

  /// True when the last target has been reached.
  bool finished() const { return next_target_ == targets_.size(); }

  /// The true state; its pose is what the tracking error measures.
  const RobotState& state() const { return state_; }

  /// The pose the robot believes it has: the true one plus the navigation error.
  Pose2 estimatedPose() const;

  /// The lake's disturbances as they are now.
  const EnvironmentDisturbance& disturbance() const { return disturbance_; }

  /// Index of the target the robot drives to; targets().size() once finished.
  std::size_t nextTarget() const { return next_target_; }

  const std::vector<Pose2>& targets() const { return targets_; }

  /// Where the reference asked for more than the vehicle can do, so far.
  const ReferenceExcess& referenceExcess() const { return reference_excess_; }

  /// The reference p_d(t) the robot tracks (times from its start), for controllers timed
  /// and pose_stream; nullptr for setpoint and los.
  const TimedReference* reference() const { return reference_ ? &*reference_ : nullptr; }

 private:
  /// The controllers' commands for this step: a surge speed (m/s, >= 0) and a yaw rate.
  struct Command {
    double speed = 0.0;
    double yaw_rate = 0.0;
  };

  bool reached(std::size_t index) const;
  void skipReachedTargets();
  /// controller: setpoint. The commands towards the next target.
  Command setpointCommand() const;
  /// controller: los. The guidance law's course and the reference's speed, or a turn in
  /// place towards a heading target.
  Command lineOfSightCommand() const;
  /// controller: los. The guidance and each piece's speed from the trajectory's `times`.
  void setUpLineOfSight(const std::vector<double>& times);
  void advanceKinematic(const Command& command);
  /// `previous_reference`: m/s, the surge-speed reference at the start of the step.
  void advanceDynamic(const Command& command, double previous_reference);
  /// The dynamic vehicle under `forces` for one step, in the lake's current.
  void advanceBody(const BodyForces& forces);
  /// controllers setpoint and los: the commands towards the next target, applied for a step.
  void advanceSetpoint();
  /// controller: timed. The law on the reference, applied for a step.
  void advanceTimed();
  /// controller: timed. The target the reference heads to, or the end once arrived.
  void updateTimedProgress();
  /// The forces of the timed controller: feedforward plus PD on the reference, per axis;
  /// without sway actuation the heading steers towards `ahead`, the reference 1 / wn later.
  BodyForces timedForces(const ReferenceState& reference, const ReferenceState& ahead) const;
  /// What the reference's own demand at `reference` asks beyond the vehicle
  /// (ReferenceExcess), if anything.
  std::optional<std::string> beyondVehicle(const ReferenceState& reference) const;
  /// The kinematic vehicle's command under the timed controller.
  Command timedCommand(const ReferenceState& reference) const;

  RobotModel model_;
  std::vector<Pose2> targets_;
  std::optional<TimedReference> reference_;           ///< controllers timed and pose_stream
  std::optional<LineOfSightGuidance> line_of_sight_;  ///< controller: los
  /// Per target, controller los: m/s, the reference's speed on the piece that leads to it.
  std::vector<double> piece_speed_;
  Point2 start_position_ = Point2::Zero();  ///< where the robot started
  /// Per target: true for a heading target (same position as the target before it).
  std::vector<bool> heading_target_;
  /// Per target: m along the targets from it to the next stop (0 at a stop), for braking.
  std::vector<double> distance_to_stop_;
  RobotState state_;
  PlanarRigidBody body_;
  EnvironmentDisturbance disturbance_;
  /// m/s: the surge-speed reference, the speed command limited by a_max.
  double speed_reference_ = 0.0;
  ReferenceExcess reference_excess_;
  double start_time_ = 0.0;  ///< state_.t at the start: t = start + steps * sim_dt
  std::size_t steps_ = 0;
  std::size_t next_target_ = 0;
};

}  // namespace kinematic_coverage::core
