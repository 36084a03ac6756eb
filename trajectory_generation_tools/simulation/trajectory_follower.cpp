#include "trajectory_generation_tools/simulation/trajectory_follower.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Relative margin above a limit before a reference's demand counts as beyond it, so that a
/// reference planned at exactly v_max or yaw_rate_max does not.
constexpr double kDemandSlack = 1e-6;

/// m/s: below this surge speed through the water the sideslip angle is left out.
constexpr double kSlowestCourseSpeed = 0.05;

bool isFinite(const Pose2& pose) {
  return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw);
}

std::string missingTimes(const char* controller) {
  return std::string("trajectory follower: controller ") + controller +
         " needs the trajectory's times (its t column); controllers setpoint and pose_stream "
         "follow poses alone";
}

/// s: pose i released at i / rate (controller: pose_stream).
std::vector<double> streamTimes(std::size_t count, double rate) {
  std::vector<double> times(count);
  for (std::size_t i = 0; i < count; ++i) times[i] = static_cast<double>(i) / rate;
  return times;
}

}  // namespace

TrajectoryFollower::TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets,
                                       const RobotState& start, std::vector<double> times)
    : TrajectoryFollower(
          model, std::move(targets), start,
          EnvironmentDisturbance(model.disturbance, model.current_x, model.current_y),
          std::move(times)) {}

TrajectoryFollower::TrajectoryFollower(const RobotModel& model, std::vector<Pose2> targets,
                                       const RobotState& start, const EnvironmentDisturbance& lake,
                                       std::vector<double> times)
    : model_(model),
      targets_(std::move(targets)),
      state_(start),
      body_(model.body, model.current_x, model.current_y),
      disturbance_(lake) {
  if (targets_.empty()) throw InvalidInputError("trajectory follower: no poses to follow");
  heading_target_.resize(targets_.size(), false);
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    if (!isFinite(targets_[i])) {
      throw InvalidInputError("trajectory follower: pose " + std::to_string(i) + " is not finite");
    }
    heading_target_[i] = i > 0 && (targets_[i].position() - targets_[i - 1].position()).norm() <=
                                      kSamePositionTolerance;
  }
  // A stop: the last target, and a position target followed by a heading target.
  distance_to_stop_.assign(targets_.size(), 0.0);
  for (std::size_t i = targets_.size() - 1; i-- > 0;) {
    if (heading_target_[i + 1]) continue;
    distance_to_stop_[i] =
        (targets_[i + 1].position() - targets_[i].position()).norm() + distance_to_stop_[i + 1];
  }
  if (!isFinite(state_.pose) || !std::isfinite(state_.t) || !std::isfinite(state_.speed) ||
      !std::isfinite(state_.sway) || !std::isfinite(state_.yaw_rate)) {
    throw InvalidInputError("trajectory follower: the start state must be finite");
  }
  state_.pose.yaw = wrapAngle(state_.pose.yaw);
  if (model_.vehicle_model == VehicleModel::kKinematic) {
    state_.speed = std::max(state_.speed, 0.0);
    state_.sway = 0.0;
  }
  speed_reference_ = std::max(state_.speed, 0.0);
  start_time_ = state_.t;
  start_position_ = state_.pose.position();
  switch (model_.controller) {
    case TrackingController::kTimed:
      if (times.empty()) throw InvalidInputError(missingTimes("timed"));
      reference_.emplace(targets_, std::move(times));
      return;
    case TrackingController::kPoseStream:
      reference_.emplace(targets_, streamTimes(targets_.size(), model_.pose_rate));
      return;
    case TrackingController::kLos:
      if (times.empty()) throw InvalidInputError(missingTimes("los"));
      setUpLineOfSight(times);
      break;
    case TrackingController::kSetpoint:
      break;
  }
  skipReachedTargets();
}

void TrajectoryFollower::setUpLineOfSight(const std::vector<double>& times) {
  if (times.size() != targets_.size()) {
    throw InvalidInputError("trajectory follower: " + std::to_string(times.size()) + " times for " +
                            std::to_string(targets_.size()) + " poses");
  }
  line_of_sight_.emplace(model_.los_lookahead > 0.0 ? model_.los_lookahead
                                                    : model_.vehicle.turning_radius);
  // The surge speed that the reference asks for on the piece to each target: its length
  // over its duration (v_max for a piece of no duration).
  piece_speed_.assign(targets_.size(), model_.vehicle.v_max);
  for (std::size_t i = 1; i < targets_.size(); ++i) {
    const double duration = times[i] - times[i - 1];
    if (!std::isfinite(duration) || duration < 0.0) {
      throw InvalidInputError(
          "trajectory follower: the trajectory's times decrease or are not finite at pose " +
          std::to_string(i));
    }
    const double length = (targets_[i].position() - targets_[i - 1].position()).norm();
    if (duration > 0.0) piece_speed_[i] = std::min(model_.vehicle.v_max, length / duration);
  }
}

Pose2 TrajectoryFollower::estimatedPose() const {
  const Point2 error = disturbance_.navigationError();
  return {state_.pose.x + error.x(), state_.pose.y + error.y(), state_.pose.yaw};
}

bool TrajectoryFollower::reached(std::size_t index) const {
  const Pose2& target = targets_[index];
  if (heading_target_[index]) {
    return std::abs(wrapAngle(target.yaw - state_.pose.yaw)) <= model_.yaw_tolerance;
  }
  const Point2 offset = estimatedPose().position() - target.position();
  const Point2 along(std::cos(target.yaw), std::sin(target.yaw));
  return offset.norm() <= model_.position_tolerance || offset.dot(along) >= 0.0;
}

void TrajectoryFollower::skipReachedTargets() {
  while (next_target_ < targets_.size() && reached(next_target_)) ++next_target_;
}

TrajectoryFollower::Command TrajectoryFollower::setpointCommand() const {
  const RobotModel& p = model_;
  const VehicleLimits& limits = model_.vehicle;
  const Pose2& target = targets_[next_target_];
  double heading_error = 0.0;
  Command command;
  if (heading_target_[next_target_]) {
    heading_error = wrapAngle(target.yaw - state_.pose.yaw);
  } else {
    // The velocity over ground the position controller asks for, and the velocity through
    // the water that gives it in the current.
    const Point2 to_target = target.position() - estimatedPose().position();
    const double braking_speed =
        p.braking
            ? std::sqrt(2.0 * limits.a_max * (to_target.norm() + distance_to_stop_[next_target_]))
            : limits.v_max;
    const Point2 over_ground =
        std::min({limits.v_max, p.position_gain * to_target.norm(), braking_speed}) *
        to_target.normalized();
    const Point2 through_water = over_ground - Point2(p.current_x, p.current_y);
    heading_error = wrapAngle(std::atan2(through_water.y(), through_water.x()) - state_.pose.yaw);
    command.speed = std::min(limits.v_max, through_water.norm());
  }
  command.yaw_rate =
      std::clamp(p.yaw_gain * heading_error, -limits.yaw_rate_max, limits.yaw_rate_max);
  command.speed = std::min(command.speed,
                           limits.v_max * (1.0 - std::abs(command.yaw_rate) / limits.yaw_rate_max));
  return command;
}

void TrajectoryFollower::advanceKinematic(const Command& command) {
  const double dt = model_.sim_dt;
  state_.speed = speed_reference_;
  state_.yaw_rate = command.yaw_rate;
  state_.pose.yaw = wrapAngle(state_.pose.yaw + command.yaw_rate * dt);
  const Point2 velocity =
      state_.speed * Point2(std::cos(state_.pose.yaw), std::sin(state_.pose.yaw)) +
      disturbance_.current();
  state_.pose.x += velocity.x() * dt;
  state_.pose.y += velocity.y() * dt;
}

void TrajectoryFollower::advanceDynamic(const Command& command, double previous_reference) {
  const RigidBodyParameters& b = model_.body;
  BodyForces forces;
  // The reference's change over the step, fed forward, and the error at the step's start:
  // a body on its reference stays on it.
  const double reference_acceleration = (speed_reference_ - previous_reference) / model_.sim_dt;
  forces.surge = b.surgeInertia() * (reference_acceleration +
                                     model_.surge_loop_gain * (previous_reference - state_.speed)) +
                 b.surgeDamping(speed_reference_);
  forces.yaw_torque =
      b.yawInertia() * model_.yaw_rate_loop_gain * (command.yaw_rate - state_.yaw_rate) +
      b.yawDamping(command.yaw_rate);
  if (b.sway_actuated) {
    // No sideslip through the water: the Coriolis force that slips a turning body outwards
    // fed forward, and the sway speed's error on the surge loop's bandwidth.
    forces.sway = b.surgeInertia() * state_.speed * state_.yaw_rate -
                  b.swayInertia() * model_.surge_loop_gain * state_.sway;
  }
  advanceBody(forces);
}

void TrajectoryFollower::advanceBody(const BodyForces& forces) {
  const Point2 current = disturbance_.current();
  body_.setCurrent(current.x(), current.y());
  const RigidBodyState next = body_.advance(
      {state_.pose, state_.speed, state_.sway, state_.yaw_rate}, forces, model_.sim_dt);
  state_.pose = next.pose;
  state_.speed = next.surge;
  state_.sway = next.sway;
  state_.yaw_rate = next.yaw_rate;
}

BodyForces TrajectoryFollower::timedForces(const ReferenceState& reference,
                                           const ReferenceState& ahead) const {
  // Per world axis, the acceleration a_d + Kd / M (v_d - v) + Kp / M (p_d - p), with
  // Kp = M wn^2 and Kd = 2 zeta wn M; in the body frame, the rigid body's Coriolis terms
  // cancelled and its damping at the reference velocity fed forward (sway actuated). The
  // controller knows the mean current, not its fluctuation, and steers by its estimate.
  const RigidBodyParameters& b = model_.body;
  const double wn = model_.tracking_natural_frequency;
  const double zeta = model_.tracking_damping;
  const Pose2 estimate = estimatedPose();
  const double c = std::cos(state_.pose.yaw);
  const double s = std::sin(state_.pose.yaw);
  const double u = state_.speed;
  const double v = state_.sway;
  const double r = state_.yaw_rate;
  const Point2 current(model_.current_x, model_.current_y);
  const Point2 over_ground = Point2(c * u - s * v, s * u + c * v) + current;
  const Point2 wanted = reference.acceleration +
                        2.0 * zeta * wn * (reference.velocity - over_ground) +
                        wn * wn * (reference.position - estimate.position());
  // Heading: the same PD on the reference's heading; a body that cannot push sideways
  // steers towards the reference a little ahead instead, turning its surge onto the
  // lateral error.
  double heading = reference.yaw;
  double yaw_rate = reference.yaw_rate;
  const Point2 to_ahead = ahead.position - estimate.position();
  if (!b.sway_actuated && to_ahead.norm() > model_.position_tolerance) {
    heading = std::atan2(to_ahead.y(), to_ahead.x());
    yaw_rate = 0.0;
  }
  const double heading_error = wrapAngle(heading - state_.pose.yaw);
  const Point2 through_water = reference.velocity - current;
  RigidBodyState damped;
  damped.surge = c * through_water.x() + s * through_water.y();
  damped.sway = -s * through_water.x() + c * through_water.y();
  damped.yaw_rate = yaw_rate;
  BodyForces forces =
      body_.forcesFor({state_.pose, u, v, r}, wanted,
                      2.0 * zeta * wn * (yaw_rate - r) + wn * wn * heading_error, damped);
  if (!b.sway_actuated) forces.sway = 0.0;
  return forces;
}

TrajectoryFollower::Command TrajectoryFollower::timedCommand(
    const ReferenceState& reference) const {
  // The kinematic vehicle takes speed and yaw rate: the reference's velocity plus wn times
  // the position error, steered by yaw_gain (towards the reference's heading at rest).
  const VehicleLimits& limits = model_.vehicle;
  const Point2 wanted =
      reference.velocity +
      model_.tracking_natural_frequency * (reference.position - estimatedPose().position()) -
      Point2(model_.current_x, model_.current_y);
  const double heading =
      wanted.norm() > model_.position_tolerance * model_.tracking_natural_frequency
          ? std::atan2(wanted.y(), wanted.x())
          : reference.yaw;
  Command command;
  command.yaw_rate = std::clamp(model_.yaw_gain * wrapAngle(heading - state_.pose.yaw),
                                -limits.yaw_rate_max, limits.yaw_rate_max);
  const Point2 along(std::cos(state_.pose.yaw), std::sin(state_.pose.yaw));
  command.speed = std::clamp(wanted.dot(along), 0.0, limits.v_max);
  return command;
}

std::optional<std::string> TrajectoryFollower::beyondVehicle(
    const ReferenceState& reference) const {
  const VehicleLimits& limits = model_.vehicle;
  const Point2 through_water = reference.velocity - Point2(model_.current_x, model_.current_y);
  const double r = reference.yaw_rate;
  if (through_water.norm() > limits.v_max * (1.0 + kDemandSlack)) {
    return "a speed through the water of " + formatNumber(through_water.norm()) +
           " m/s, beyond v_max = " + formatNumber(limits.v_max) + " m/s";
  }
  if (std::abs(r) > limits.yaw_rate_max * (1.0 + kDemandSlack)) {
    return "a yaw rate of " + formatNumber(std::abs(r)) +
           " rad/s, beyond yaw_rate_max = " + formatNumber(limits.yaw_rate_max) + " rad/s";
  }
  if (model_.vehicle_model == VehicleModel::kKinematic) return std::nullopt;
  // The reference's own demand: its acceleration, at its heading and velocity through the
  // water (its yaw acceleration left out).
  const RigidBodyParameters& b = model_.body;
  const double c = std::cos(reference.yaw);
  const double s = std::sin(reference.yaw);
  RigidBodyState at_reference;
  at_reference.pose.yaw = reference.yaw;
  at_reference.surge = c * through_water.x() + s * through_water.y();
  at_reference.sway = -s * through_water.x() + c * through_water.y();
  at_reference.yaw_rate = r;
  const BodyForces demand =
      body_.forcesFor(at_reference, reference.acceleration, 0.0, at_reference);
  bool beyond = false;
  if (b.sway_actuated) {
    const BodyForces given = body_.limited(demand);
    beyond = std::hypot(demand.surge - given.surge, demand.sway - given.sway) >
                 kDemandSlack * b.thrust_max ||
             std::abs(demand.yaw_torque - given.yaw_torque) > kDemandSlack * b.yaw_torque_max;
  } else {
    // The torpedo turns its surge onto the path instead of pushing sideways.
    beyond = std::abs(demand.surge) > b.thrust_max * (1.0 + kDemandSlack) ||
             std::abs(demand.yaw_torque) > b.yaw_torque_max * (1.0 + kDemandSlack);
  }
  if (!beyond) return std::nullopt;
  return "more thrust than the thrusters give (surge " + formatNumber(demand.surge) + " N, sway " +
         formatNumber(demand.sway) + " N, yaw " + formatNumber(demand.yaw_torque) + " N m)";
}

void TrajectoryFollower::advanceTimed() {
  // The trajectory's times count from its start, which a robot handed a new trajectory
  // mid-mission reaches at start_time_.
  const double elapsed = state_.t - start_time_;
  const ReferenceState reference = reference_->at(elapsed);
  if (const std::optional<std::string> demand = beyondVehicle(reference)) {
    if (reference_excess_.duration_s == 0.0) {
      reference_excess_.first_demand = *demand;
      reference_excess_.first_t = state_.t;
      reference_excess_.first_position = reference.position;
      reference_excess_.first_pose = reference_->pieceEnd(elapsed);
    }
    reference_excess_.duration_s += model_.sim_dt;
  }
  if (model_.vehicle_model == VehicleModel::kKinematic) {
    const Command command = timedCommand(reference);
    speed_reference_ = command.speed;
    advanceKinematic(command);
  } else {
    const double lookahead_s = 1.0 / model_.tracking_natural_frequency;
    advanceBody(timedForces(reference, reference_->at(elapsed + lookahead_s)));
  }
}

void TrajectoryFollower::updateTimedProgress() {
  // Done once the reference has ended and the robot is at its last pose, with its heading;
  // a body that cannot push sideways (nor hold a heading on the spot against a lateral
  // error) is done once at or past the last pose, as the setpoint follower is.
  const Pose2& last = reference_->lastPose();
  const double elapsed = state_.t - start_time_;
  const Point2 offset = estimatedPose().position() - last.position();
  const bool lateral = model_.vehicle_model == VehicleModel::kDynamic && model_.body.sway_actuated;
  bool arrived = false;
  if (lateral) {
    arrived = offset.norm() <= model_.position_tolerance &&
              std::abs(wrapAngle(last.yaw - state_.pose.yaw)) <= model_.yaw_tolerance;
  } else {
    // The last position target reached (or passed), then the heading of a last rotation.
    std::size_t last_position = targets_.size() - 1;
    while (heading_target_[last_position]) --last_position;
    arrived = reached(last_position) && reached(targets_.size() - 1);
  }
  if (elapsed >= reference_->endTime() && arrived) {
    next_target_ = targets_.size();
  } else {
    next_target_ = std::min(reference_->pieceEnd(elapsed), targets_.size() - 1);
  }
}

TrajectoryFollower::Command TrajectoryFollower::lineOfSightCommand() const {
  const VehicleLimits& limits = model_.vehicle;
  const Pose2& target = targets_[next_target_];
  const Pose2 estimate = estimatedPose();
  Command command;
  double heading_error = 0.0;
  if (heading_target_[next_target_]) {
    heading_error = wrapAngle(target.yaw - state_.pose.yaw);
  } else {
    // The guidance law's course at the reference's speed on this piece, braked in time for
    // the next stop; the velocity through the water that gives it in the mean current (the
    // crab angle), steered less the sideslip through the water that the robot measures.
    const Point2 from = next_target_ == 0 ? start_position_ : targets_[next_target_ - 1].position();
    const double course = line_of_sight_->course(from, target.position(), estimate.position());
    const double to_stop =
        (target.position() - estimate.position()).norm() + distance_to_stop_[next_target_];
    const double speed =
        std::min(piece_speed_[next_target_], std::sqrt(2.0 * limits.a_max * to_stop));
    const Point2 through_water = speed * Point2(std::cos(course), std::sin(course)) -
                                 Point2(model_.current_x, model_.current_y);
    const double sideslip =
        state_.speed > kSlowestCourseSpeed ? std::atan2(state_.sway, state_.speed) : 0.0;
    heading_error =
        wrapAngle(std::atan2(through_water.y(), through_water.x()) - sideslip - state_.pose.yaw);
    command.speed =
        std::min(limits.v_max, through_water.norm()) * std::max(0.0, std::cos(heading_error));
  }
  command.yaw_rate =
      std::clamp(model_.yaw_gain * heading_error, -limits.yaw_rate_max, limits.yaw_rate_max);
  return command;
}

void TrajectoryFollower::advanceSetpoint() {
  const Command command = line_of_sight_ ? lineOfSightCommand() : setpointCommand();
  const double speed_change = model_.vehicle.a_max * model_.sim_dt;
  const double previous_reference = speed_reference_;
  speed_reference_ = std::max(0.0, speed_reference_ + std::clamp(command.speed - speed_reference_,
                                                                 -speed_change, speed_change));
  if (model_.vehicle_model == VehicleModel::kKinematic) {
    advanceKinematic(command);
  } else {
    advanceDynamic(command, previous_reference);
  }
}

void TrajectoryFollower::step() {
  if (finished()) return;
  if (reference_) {
    advanceTimed();
  } else {
    advanceSetpoint();
  }
  disturbance_.advance(model_.sim_dt);
  ++steps_;
  state_.t = start_time_ + static_cast<double>(steps_) * model_.sim_dt;
  if (reference_) {
    updateTimedProgress();
  } else {
    skipReachedTargets();
  }
}

}  // namespace kinematic_coverage::core
